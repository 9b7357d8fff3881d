"""The two kernels that open and close every step.

Fused so that the fixed per-step cost of calling into compiled code stays
small: each kernel call from Python unboxes the whole body table.
"""
from __future__ import annotations

from ._jit import kernel
from .checkpoint import count_nonfinite, save_state
from .geometry import update_geometry


@kernel
def begin_step(B, V, n, dt, spec, X, Q, Vel, W):
    """Save the last finite state, then refresh world geometry and AABBs."""
    save_state(B, n, X, Q, Vel, W)
    update_geometry(B, V, n, dt, spec)


@kernel
def end_step(B, n, bad):
    """Count non-finite bodies (slots into ``bad``); clear user forces when all is finite."""
    k = count_nonfinite(B, n, bad)
    if k == 0:
        for i in range(n):
            B.f[i, 0] = 0.0
            B.f[i, 1] = 0.0
            B.tau[i] = 0.0
    return k
