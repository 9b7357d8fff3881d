"""The two kernels that open and close every step.

Fused so that the fixed per-step cost of calling into compiled code stays
small: each kernel call from Python unboxes the whole body table.
"""
from __future__ import annotations

from .._jit import kernel
from ..geometry.transform import update_geometry
from .checkpoint import count_nonfinite, save_state


# _nrt=False (both kernels, and the helpers they call): they allocate nothing, and without
# numba's runtime the per-fixture and per-body reads of the table columns cost no atomic
# reference-count updates (pyramid20: begin_step 280 us -> 90 us on the loaded 2-core VM)
@kernel(_nrt=False)
def begin_step(ctx, B, F, V, nf, X, Q, Vel, W):
    """Save the last finite state, then refresh the ``nf`` fixtures' world geometry and AABBs."""
    c = ctx[0]
    save_state(B, c.n, X, Q, Vel, W)
    update_geometry(B, F, V, c.n, nf, c.dt, c.spec)


@kernel(_nrt=False)
def end_step(ctx, B, S, bad, why):
    """Count bodies whose state or energy is not finite (slots into ``bad``, the reason in
    ``why``: checkpoint.count_nonfinite); clear user forces when all is finite."""
    c = ctx[0]
    n = c.n
    k = count_nonfinite(B, n, S, c.ns, bad, why)
    if k == 0:
        for i in range(n):
            B.f[i, 0] = 0.0
            B.f[i, 1] = 0.0
            B.tau[i] = 0.0
    return k
