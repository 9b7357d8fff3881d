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
from ..store.slot_list import at
from .checkpoint import count_nonfinite, save_state
from .contact_events import touch_update
from .energy_sums import PUSH, SUMS, guard_sums
from .push_out import push_sum


@kernel(entry=True)
def begin_step(ctx, B, F, V, nf, X, Q, Vel, W, S, sums, full, nthr, act, nact, actf, nactf, rest):
    """Save the last finite state of the ``nact`` bodies listed in ``act`` (store/slot_list.py:
    the awake ones, step/active.py, or every body), refresh the fixtures' world geometry and
    AABBs (the ``nactf`` listed in ``actf``, or all of them when ``full``: update_geometry); the
    energy guard's sums of the state the step starts from into ``sums`` (energy_sums.py, the
    unlisted bodies' sums in ``rest``).  ``nthr``: threads for the geometry (None: the serial
    build, physics/threads.py)."""
    c = ctx[0]
    save_state(B, act, nact, X, Q, Vel, W)
    guard_sums(B, S, act, nact, c.ns, c.gx, c.gy, rest, sums)
    update_geometry(B, F, V, c.n, nf, c.dt, c.spec, full, nthr, actf, nactf)


@kernel(entry=True)
def end_step(ctx, B, S, bad, why, Ca, Cb, nc, cluster, sums, key, npts, depth, jn, prev, nprev, out, begin,
             absent, act, nact, rows, nrows, rest):
    """Count bodies whose state or energy is not finite among the ``nrows`` listed in ``rows``
    (store/slot_list.py: every body a step can change, step/active.py; slots into ``bad``, the
    reason in ``why``: checkpoint.count_nonfinite); when all is finite, the energy guard's sums of
    the state the step ends in (over the ``nact`` bodies in ``act`` and the others' ``rest``, with
    the push-out allowance of its ``nc`` contacts at the mode's push-out speed ``c.push_speed``:
    push_out.push_sum, ``cluster`` its scratch) into ``sums``, and clear user forces.  Then the
    touching merge of the ``nc`` rows (``key``, ``npts``, ``depth``, ``jn``) with last step's keys
    ``prev[:nprev]`` into ``out``, ``begin``, ``absent`` (contact_events.touch_update; kept only if
    the step is accepted).  Returns the non-finite count and the merge's three counts."""
    c = ctx[0]
    k = count_nonfinite(B, rows, nrows, S, c.ns, bad, why)
    if k == 0:
        guard_sums(B, S, act, nact, c.ns, c.gx, c.gy, rest, sums)
        g = (c.gx * c.gx + c.gy * c.gy) ** 0.5
        sums[PUSH] = push_sum(B, rows, nrows, Ca, Cb, npts, depth, nc, c.push_speed, g, cluster)
        for j in range(nrows):
            i = at(rows, j)
            B.f[i, 0] = 0.0
            B.f[i, 1] = 0.0
            B.tau[i] = 0.0
    nt, nb, na = touch_update(key, npts, depth, jn, nc, c.slop, prev, nprev, out, begin, absent)
    return k, nt, nb, na


@kernel(entry=True, runtime=True)
def begin_step_flat(ctx, BF, BI, FF, FI, ghost, wghost, VF, VI, nf, X, Q, Vel, W, SF, SI, sums):
    """``begin_step`` of every body over the tables' flat arrays."""
    B = bodies_view(BF, BI)
    every = np.zeros(0, np.int64)  # store/slot_list.ALL
    begin_step(ctx, B, fixtures_view(FF, FI, ghost, wghost), verts_view(VF, VI), nf, X, Q, Vel, W,
               springs_view(SF, SI), sums, np.bool_(True), None, every, ctx[0].n, every, nf, np.zeros(SUMS))


@kernel(entry=True, runtime=True)
def end_step_flat(ctx, BF, BI, SF, SI, bad, why, Ca, Cb, nc, cluster, sums, key, npts, depth, jn, prev, nprev,
                  out, begin, absent):
    """``end_step`` of every body over the body and spring tables' flat arrays."""
    every = np.zeros(0, np.int64)  # store/slot_list.ALL
    n = ctx[0].n
    return end_step(ctx, bodies_view(BF, BI), springs_view(SF, SI), bad, why, Ca, Cb, nc, cluster, sums, key, npts,
                    depth, jn, prev, nprev, out, begin, absent, every, n, every, n, np.zeros(SUMS))
