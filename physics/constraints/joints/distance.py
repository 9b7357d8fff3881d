"""Distance joint: a rod, a spring or a rope between two anchors.

With d = p_a - p_b, L = |d| and u = d / L, every row acts along u (ka = r_a x u):
EQ0 holds L at ``length`` when the joint is a rigid rod (no spring, no limits);
otherwise the spring pulls towards ``length`` and the limit rows keep L within
[lower, upper] (a rope: an upper limit only).  Box2D v3's distance_joint.c.
"""
from __future__ import annotations

import math

from .jit import row_inline, row_part
from ...store.joints import EQ0, EQ1, EQ2, LOWER, MOTOR_ROW, SPRING, UPPER
from ..body_rows import II, IM
from .frame import arms, cross
from .rows import clear_row, set_row
from .soft_rows import rigid_row, spring_softness

MIN_LENGTH = 1e-9  # below this the direction is undefined and the rows are idle


@row_inline
def is_rod(J, j):
    """A rigid rod: no spring and no limits."""
    return J.hertz[j] <= 0.0 and math.isnan(J.lower[j]) and math.isnan(J.upper[j])


@row_part
def prepare_distance(J, JW, j, h):
    if is_rod(J, j):
        rigid_row(JW, j, 0)
        return 1 << EQ0
    mask = 0
    if J.hertz[j] > 0.0:
        spring_softness(JW, j, J.hertz[j], J.zeta[j], h)
        mask |= 1 << SPRING
    if not math.isnan(J.lower[j]):
        mask |= 1 << LOWER
    if not math.isnan(J.upper[j]):
        mask |= 1 << UPPER
    return mask


@row_part
def rows_distance(B, J, JW, j, a, b):
    ims = JW.SB[a, IM] + JW.SB[b, IM]
    iia = JW.SB[a, II]
    iib = JW.SB[b, II]
    rax, ray, rbx, rby, dx, dy = arms(JW, j, a, b)
    length = math.hypot(dx, dy)
    ux = 0.0
    uy = 0.0
    if length > MIN_LENGTH:
        ux = dx / length
        uy = dy / length
    ka = cross(rax, ray, ux, uy)
    kb = cross(rbx, rby, ux, uy)
    c = length - J.length[j]
    set_row(JW, j, EQ0, ux, uy, ka, kb, c, ims, iia, iib)
    set_row(JW, j, SPRING, ux, uy, ka, kb, c, ims, iia, iib)
    lo = J.lower[j]
    hi = J.upper[j]
    set_row(JW, j, LOWER, ux, uy, ka, kb, 0.0 if math.isnan(lo) else length - lo, ims, iia, iib)
    set_row(JW, j, UPPER, -ux, -uy, -ka, -kb, 0.0 if math.isnan(hi) else hi - length, ims, iia, iib)
    clear_row(JW, j, EQ1)
    clear_row(JW, j, EQ2)
    clear_row(JW, j, MOTOR_ROW)
