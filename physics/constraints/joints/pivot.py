"""Which anchor the rotation cap turns each jointed body about (constraints/rotation_cap.py).

The move caps each body's rotation per sub-step (rotation_cap.MAX_ROTATION, as Box2D v3's
b2IntegratePositionsTask), keeping the velocity of the centre of mass.  For a body held by a joint
away from its centre (a bob on a rod spun faster than the cap) that breaks the rigid motion the
joint solve produced: the body translates at the uncapped speed while it turns at the capped one,
its anchor leaves the joint by metres, and the next sub-steps' impulses, applied at an anchor that
is no longer where the joint is, feed angular momentum about the pivot into it (energy grew about
2.5x per step).  Capping about the anchor instead keeps the anchor's velocity, so the joint stays
satisfied: v' = v + (w - w_cap) x r, r the anchor's arm.  A body on several joints is capped about
one of them: a joint to the world or a static body first, else the first; the cap never adds
kinetic energy (otherwise it falls back to the centre of mass)."""
from __future__ import annotations

from ...store import DYNAMIC
from ..rotation_cap import PX, PY, RANK
from .jit import row_kernel


@row_kernel
def save_pivots(c, B, J, JW, PV):
    """PV[i, PX:RANK + 1]: the anchor body i is capped about (rank 2: a joint to the world or a
    static body, 1: to a moving body, 0: none).  ``PV``: per-body scratch, rotation_cap's columns
    (kept out of the joint scratch, which every per-joint call passes)."""
    ja, jb, la, lb, on, kind = J.a, J.b, J.la, J.lb, JW.on, B.kind  # each column's view built once
    for i in range(c.n):
        PV[i, RANK] = 0.0
    for j in range(c.nj):
        if on[j] == 0:
            continue
        for side in range(2):
            i = ja[j] if side == 0 else jb[j]
            o = jb[j] if side == 0 else ja[j]
            if i < 0 or kind[i] != DYNAMIC:
                continue
            rank = 2.0 if o < 0 or kind[o] != DYNAMIC else 1.0
            if rank > PV[i, RANK]:
                PV[i, PX] = la[j, 0] if side == 0 else lb[j, 0]
                PV[i, PY] = la[j, 1] if side == 0 else lb[j, 1]
                PV[i, RANK] = rank
