"""Once per step: which joints take part, their frames, softness and clamps.

A joint is on while it is not broken and one of its bodies is an awake
dynamic body.  Its frame (layout.py) is taken from the bodies' state at the
step start; ``h`` is the span of one pass (soft_step's sub-step, a whole step
for sequential impulses, a classic sub-step) and ``js`` the mode's joint
softness (bias rate, mass scale, impulse scale) for the biased passes.  The
world is the extra body row n, which never moves.
"""
from __future__ import annotations

import math

from .jit import row_entry, row_inline, row_kernel
from ...store import DYNAMIC
from ...store.joints import BROKEN, DISTANCE, EQUALITY
from ..body_rows import DCOS, II
from .dispatch import joint_prepare
from .distance import is_rod
from .layout import D0, MASS_ANG, RA0, RB0, SOFT_LIMIT, U0


@row_entry
def equality_count(J, j):
    """How many equality rows joint j has (0 for motor and mouse joints, ropes, springs, broken)."""
    if J.flags[j] & BROKEN:
        return 0
    k = J.kind[j]
    if k == DISTANCE and not is_rod(J, j):
        return 0
    return EQUALITY[k]


@row_entry
def equality_counts(J, nj, out):
    for j in range(nj):
        out[j] = equality_count(J, j)


@row_inline
def awake_dynamic(B, i):
    return i >= 0 and B.kind[i] == DYNAMIC and B.awake[i] == 1


@row_inline
def prepare_frame(B, J, JW, j, a, b):
    F = JW.F
    qa = B.q[a]
    ca = math.cos(qa)
    sa = math.sin(qa)
    F[j, RA0] = ca * J.la[j, 0] - sa * J.la[j, 1]
    F[j, RA0 + 1] = sa * J.la[j, 0] + ca * J.la[j, 1]
    F[j, U0] = ca * J.axis[j, 0] - sa * J.axis[j, 1]
    F[j, U0 + 1] = sa * J.axis[j, 0] + ca * J.axis[j, 1]
    if J.b[j] >= 0:
        qb = B.q[b]
        cb = math.cos(qb)
        sb = math.sin(qb)
        F[j, RB0] = cb * J.lb[j, 0] - sb * J.lb[j, 1]
        F[j, RB0 + 1] = sb * J.lb[j, 0] + cb * J.lb[j, 1]
        F[j, D0] = B.x[a, 0] - B.x[b, 0]
        F[j, D0 + 1] = B.x[a, 1] - B.x[b, 1]
    else:  # the world: its "arm" is the world point itself, seen from the origin
        F[j, RB0] = J.lb[j, 0]
        F[j, RB0 + 1] = J.lb[j, 1]
        F[j, D0] = B.x[a, 0]
        F[j, D0 + 1] = B.x[a, 1]
    k = JW.SB[a, II] + JW.SB[b, II]
    F[j, MASS_ANG] = 1.0 / k if k > 0.0 else 0.0


@row_kernel
def prepare_joints(c, B, J, JW, h, js0, js1, js2):
    """Fill JW (ab, on, mask, F) for this step; the world body row is row c.n.  (js0, js1, js2): the
    mode's joint softness for the biased passes (rate, mass scale, impulse scale)."""
    n = c.n
    SB = JW.SB
    for f in range(SB.shape[1]):
        SB[n, f] = 0.0
    SB[n, DCOS] = 1.0
    F = JW.F
    for j in range(c.nj):
        a = J.a[j]
        b = J.b[j]
        bw = b if b >= 0 else n
        JW.ab[j, 0] = a
        JW.ab[j, 1] = bw
        on = (J.flags[j] & BROKEN) == 0 and (awake_dynamic(B, a) or awake_dynamic(B, b))
        JW.on[j] = 1 if on else 0
        JW.mask[j] = 0
        if not on:
            continue
        prepare_frame(B, J, JW, j, a, bw)
        F[j, SOFT_LIMIT] = js0
        F[j, SOFT_LIMIT + 1] = js1
        F[j, SOFT_LIMIT + 2] = js2
        JW.mask[j] = joint_prepare(J, JW, j, h)


@row_kernel
def zero_joint_impulses(J, nj):
    """Forget the accumulated impulses (warm starting switched off)."""
    for j in range(nj):
        for r in range(J.impulse.shape[1]):
            J.impulse[j, r] = 0.0
