"""The two kernels that open and close every step.

Fused so that the fixed per-step cost of calling into compiled code stays
small; the ``*_flat`` entries take the tables as their flat arrays (store/flat.py: two 2-D
arrays per table unbox in a fraction of a namedtuple of columns' time).
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from ..geometry.transform import update_geometry
from ..store.flat import bodies_view, fixtures_view, springs_view, verts_view
from .checkpoint import count_nonfinite, save_state
from .contact_events import touch_update
from .energy_sums import PUSH, guard_sums
from .push_out import push_sum


@kernel(entry=True)
def begin_step(ctx, B, F, V, nf, X, Q, Vel, W, S, sums, full, nthr):
    """Save the last finite state, then refresh the ``nf`` fixtures' world geometry and AABBs
    (all of it when ``full``: update_geometry); the energy guard's sums of the state the step
    starts from into ``sums`` (energy_sums.py).  ``nthr``: threads for the geometry (None: the
    serial build, physics/threads.py)."""
    c = ctx[0]
    save_state(B, c.n, X, Q, Vel, W)
    guard_sums(B, S, c.n, c.ns, c.gx, c.gy, sums)
    update_geometry(B, F, V, c.n, nf, c.dt, c.spec, full, nthr)


@kernel(entry=True)
def end_step(ctx, B, S, bad, why, Ca, Cb, nc, cluster, sums, key, npts, depth, jn, prev, nprev, out, begin,
             absent):
    """Count bodies whose state or energy is not finite (slots into ``bad``, the reason in
    ``why``: checkpoint.count_nonfinite); when all is finite, the energy guard's sums of the
    state the step ends in (with the push-out allowance of its ``nc`` contacts at the mode's
    push-out speed ``c.push_speed``: push_out.push_sum, ``cluster`` its scratch) into ``sums``,
    and clear user forces.  Then the touching merge of the ``nc`` rows (``key``, ``npts``,
    ``depth``, ``jn``) with last step's keys ``prev[:nprev]`` into ``out``, ``begin``, ``absent``
    (contact_events.touch_update; kept only if the step is accepted).  Returns the non-finite
    count and the merge's three counts."""
    c = ctx[0]
    n = c.n
    k = count_nonfinite(B, n, S, c.ns, bad, why)
    if k == 0:
        guard_sums(B, S, n, c.ns, c.gx, c.gy, sums)
        g = (c.gx * c.gx + c.gy * c.gy) ** 0.5
        sums[PUSH] = push_sum(B, n, Ca, Cb, npts, depth, nc, c.push_speed, g, cluster)
        for i in range(n):
            B.f[i, 0] = 0.0
            B.f[i, 1] = 0.0
            B.tau[i] = 0.0
    nt, nb, na = touch_update(key, npts, depth, jn, nc, c.slop, prev, nprev, out, begin, absent)
    return k, nt, nb, na


@kernel(entry=True, runtime=True)
def begin_step_flat(ctx, BF, BI, FF, FI, ghost, wghost, VF, VI, nf, X, Q, Vel, W, SF, SI, sums):
    """``begin_step`` over the tables' flat arrays."""
    begin_step(ctx, bodies_view(BF, BI), fixtures_view(FF, FI, ghost, wghost), verts_view(VF, VI), nf,
               X, Q, Vel, W, springs_view(SF, SI), sums, np.bool_(True), None)


@kernel(entry=True, runtime=True)
def end_step_flat(ctx, BF, BI, SF, SI, bad, why, Ca, Cb, nc, cluster, sums, key, npts, depth, jn, prev, nprev,
                  out, begin, absent):
    """``end_step`` over the body and spring tables' flat arrays."""
    return end_step(ctx, bodies_view(BF, BI), springs_view(SF, SI), bad, why, Ca, Cb, nc, cluster, sums, key, npts,
                    depth, jn, prev, nprev, out, begin, absent)
