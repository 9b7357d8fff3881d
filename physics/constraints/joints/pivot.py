"""The rotation cap about a joint's anchor instead of the centre of mass.

The move caps each body's rotation per sub-step (body_rows.MAX_ROTATION, as Box2D v3's
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

import math

from ...store import DYNAMIC
from ..body_rows import DCOS, DSIN, II, IM, MAX_ROTATION, VX, VY, W
from .jit import row_inline, row_kernel

PX, PY, RANK = range(3)  # the anchor's arm (world frame at the step's start) and its rank


@row_kernel
def save_pivots(c, B, J, JW):
    """PV[i]: the arm of the anchor body i is capped about (rank 2: a joint to the world or a
    static body, 1: to a moving body, 0: none)."""
    PV = JW.PV
    for i in range(c.n):
        PV[i, RANK] = 0.0
    for j in range(c.nj):
        if JW.on[j] == 0:
            continue
        a = J.a[j]
        b = J.b[j]
        for side in range(2):
            i = a if side == 0 else b
            o = b if side == 0 else a
            if i < 0 or B.kind[i] != DYNAMIC:
                continue
            rank = 2.0 if o < 0 or B.kind[o] != DYNAMIC else 1.0
            if rank <= PV[i, RANK]:
                continue
            lx = J.la[j, 0] if side == 0 else J.lb[j, 0]
            ly = J.la[j, 1] if side == 0 else J.lb[j, 1]
            cq = math.cos(B.q[i])
            sq = math.sin(B.q[i])
            PV[i, PX] = cq * lx - sq * ly
            PV[i, PY] = sq * lx + cq * ly
            PV[i, RANK] = rank


@row_inline
def capped(vx, vy, w, im, ii, rx, ry, h):
    """(v', w', changed): w at the cap and v so that the point at arm (rx, ry) keeps its velocity,
    v' = v + (w - w_cap) x r; unchanged (False) when that would add kinetic energy."""
    wc = math.copysign(MAX_ROTATION / h, w)
    dw = w - wc
    ux = vx - dw * ry
    uy = vy + dw * rx
    # 1/2 |v|^2 / im + 1/2 w^2 / ii may only fall
    if (ux * ux + uy * uy - vx * vx - vy * vy) * ii <= (w * w - wc * wc) * im:
        return ux, uy, wc, True
    return vx, vy, w, False


@row_kernel
def cap_about_pivots(PV, n, SB, h):
    """Body rows whose anchor turns faster than the cap, capped about it (``capped``); the others
    are left to the move, which caps w alone."""
    for i in range(n):
        w = SB[i, W]
        if PV[i, RANK] == 0.0 or abs(w * h) <= MAX_ROTATION or SB[i, IM] == 0.0 or SB[i, II] == 0.0:
            continue
        c = SB[i, DCOS]  # the turn since the step began carries the arm along
        s = SB[i, DSIN]
        rx = c * PV[i, PX] - s * PV[i, PY]
        ry = s * PV[i, PX] + c * PV[i, PY]
        vx, vy, w, ok = capped(SB[i, VX], SB[i, VY], w, SB[i, IM], SB[i, II], rx, ry, h)
        if ok:
            SB[i, VX] = vx
            SB[i, VY] = vy
            SB[i, W] = w


@row_kernel
def cap_table_about_pivots(PV, n, B, h):
    """``cap_about_pivots`` on the body table, for modes that move it once per step (the arm is
    the step start's)."""
    for i in range(n):
        w = B.w[i]
        if PV[i, RANK] == 0.0 or abs(w * h) <= MAX_ROTATION or B.inv_m[i] == 0.0 or B.inv_i[i] == 0.0:
            continue
        vx, vy, w, ok = capped(B.v[i, 0], B.v[i, 1], w, B.inv_m[i], B.inv_i[i], PV[i, PX], PV[i, PY], h)
        if ok:
            B.v[i, 0] = vx
            B.v[i, 1] = vy
            B.w[i] = w
