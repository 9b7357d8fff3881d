"""Prismatic (slider) joint: motion along an axis fixed in a, no relative rotation.

With d = p_a - p_b and the axis u (perpendicular p) turning with a, the rows are
EQ0: d . p (off-axis separation) and EQ1: the relative angle; the spring, motor
and limits act on the translation t = d . u.  A row along a direction fixed in a
has ka = (r_a - d) x n, because the direction turns with a under the separation
(Box2D v3's prismatic_joint.c, (d + r_A) x axis with the bodies' roles swapped).
"""
from __future__ import annotations

import math

from .jit import row_inline, row_part
from ...store.joints import EQ0, EQ1, EQ2, LOWER, MOTOR_ROW, SPRING, UPPER
from ..body_rows import II, IM
from .frame import arms, axis, cross, relative_angle
from .layout import MAX_MOTOR
from .rows import clear_row, set_row
from .soft_rows import rigid_row, spring_softness


@row_inline
def axial_prepare(J, JW, j, h, mask):
    """Spring, motor and limit rows along the axis (shared with the wheel)."""
    if J.hertz[j] > 0.0:
        spring_softness(JW, j, J.hertz[j], J.zeta[j], h)
        mask |= 1 << SPRING
    if not math.isnan(J.lower[j]):
        mask |= 1 << LOWER
    if not math.isnan(J.upper[j]):
        mask |= 1 << UPPER
    return mask


@row_part
def prepare_prismatic(J, JW, j, h):
    rigid_row(JW, j, 0)
    rigid_row(JW, j, 1)
    mask = axial_prepare(J, JW, j, h, (1 << EQ0) | (1 << EQ1))
    if J.max_motor[j] > 0.0:
        JW.F[j, MAX_MOTOR] = J.max_motor[j] * h
        mask |= 1 << MOTOR_ROW
    return mask


@row_inline
def slide_rows(J, JW, j, a, b, ims, iia, iib, with_motor):
    """EQ0 (off-axis) and the axial spring, limit (and motor) rows."""
    ux, uy = axis(JW, j, a)
    px = -uy
    py = ux
    rax, ray, rbx, rby, dx, dy = arms(JW, j, a, b)
    sx = rax - dx
    sy = ray - dy
    set_row(JW, j, EQ0, px, py, cross(sx, sy, px, py), cross(rbx, rby, px, py), dx * px + dy * py, ims, iia, iib)
    t = dx * ux + dy * uy
    ka = cross(sx, sy, ux, uy)
    kb = cross(rbx, rby, ux, uy)
    set_row(JW, j, SPRING, ux, uy, ka, kb, t, ims, iia, iib)
    if with_motor:
        set_row(JW, j, MOTOR_ROW, ux, uy, ka, kb, 0.0, ims, iia, iib)
    lo = J.lower[j]
    hi = J.upper[j]
    set_row(JW, j, LOWER, ux, uy, ka, kb, 0.0 if math.isnan(lo) else t - lo, ims, iia, iib)
    set_row(JW, j, UPPER, -ux, -uy, -ka, -kb, 0.0 if math.isnan(hi) else hi - t, ims, iia, iib)


@row_part
def rows_prismatic(B, J, JW, j, a, b):
    ims = JW.SB[a, IM] + JW.SB[b, IM]
    iia = JW.SB[a, II]
    iib = JW.SB[b, II]
    slide_rows(J, JW, j, a, b, ims, iia, iib, True)
    set_row(JW, j, EQ1, 0.0, 0.0, 1.0, 1.0, relative_angle(B, J, j), ims, iia, iib)
    clear_row(JW, j, EQ2)
