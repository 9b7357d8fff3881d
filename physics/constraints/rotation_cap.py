"""The rotation cap: a body turns at most MAX_ROTATION per sub-step (Box2D v3's B2_MAX_ROTATION,
b2IntegratePositionsTask), so a spinning sliver cannot tunnel through its own contacts.

Box2D keeps the centre of mass's velocity.  A body held by a joint is turned about the joint's
anchor instead (joints/pivot.py says why and which anchor): v' = v + (w - w_cap) x r, r the
anchor's arm, unless that would add kinetic energy."""
from __future__ import annotations

import math

from .._jit import kernel

MAX_ROTATION = 0.25 * math.pi
# a body's pivot in its per-body scratch row (columns 0-2 are soft_step's sub-step start velocities):
# the anchor in the body's frame (from its centre of mass) and its rank
PX, PY, RANK = 3, 4, 5
PIVOT_COLUMNS = 6  # the scratch's width


@kernel
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


@kernel
def cap_about_pivot(PV, npv, i, q, vx, vy, w, im, ii, h):
    """(v', w') of body i (angle q) at the cap: about its anchor when it has one (i < npv: the
    world has joints) and that adds no kinetic energy, else w alone, about the centre of mass."""
    if i < npv and PV[i, RANK] != 0.0 and im != 0.0 and ii != 0.0:
        cq = math.cos(q)
        sq = math.sin(q)
        rx = cq * PV[i, PX] - sq * PV[i, PY]
        ry = sq * PV[i, PX] + cq * PV[i, PY]
        ux, uy, wc, ok = capped(vx, vy, w, im, ii, rx, ry, h)
        if ok:
            return ux, uy, wc
    return vx, vy, math.copysign(MAX_ROTATION / h, w)
