"""Revolute (hinge) joint: a shared point, with an angular spring, motor and limits.

Rows (store/joints.py): EQ0, EQ1 the anchor separation along x and y; the
spring, motor and limit rows act on the relative angle q_a - q_b - ref.
Box2D v3's revolute_joint.c, with a's rotation relative to b's.
"""
from __future__ import annotations

import math

from .jit import row_inline, row_part
from ...store.joints import EQ0, EQ1, EQ2, LOWER, MOTOR_ROW, SPRING, UPPER
from ..body_rows import II, IM
from .frame import arms, relative_angle
from .layout import MAX_MOTOR
from .rows import clear_row, idle, set_row
from .soft_rows import rigid_row, spring_softness


@row_inline
def angular_prepare(J, JW, j, h, mask):
    """Softness and clamps of the spring, motor and limit rows on the relative angle (shared with
    the rotary joint), their bits added to ``mask``."""
    if J.hertz[j] > 0.0:
        spring_softness(JW, j, J.hertz[j], J.zeta[j], h)
        mask |= 1 << SPRING
    if J.max_motor[j] > 0.0:
        JW.F[j, MAX_MOTOR] = J.max_motor[j] * h
        mask |= 1 << MOTOR_ROW
    if not math.isnan(J.lower[j]):
        mask |= 1 << LOWER
    if not math.isnan(J.upper[j]):
        mask |= 1 << UPPER
    return mask


@row_part
def prepare_revolute(J, JW, j, h):
    """Softness and clamps for one step; returns the row mask."""
    rigid_row(JW, j, 0)
    rigid_row(JW, j, 1)
    return angular_prepare(J, JW, j, h, (1 << EQ0) | (1 << EQ1))


@row_inline
def angular_rows(B, J, JW, j, ims, iia, iib):
    """Spring, motor and limit rows on the relative angle (shared with the wheel's motor and the
    rotary joint)."""
    ang = relative_angle(B, J, j)
    set_row(JW, j, SPRING, 0.0, 0.0, 1.0, 1.0, ang, ims, iia, iib)
    set_row(JW, j, MOTOR_ROW, 0.0, 0.0, 1.0, 1.0, 0.0, ims, iia, iib)
    lo = J.lower[j]
    hi = J.upper[j]
    set_row(JW, j, LOWER, 0.0, 0.0, 1.0, 1.0, 0.0 if math.isnan(lo) else ang - lo, ims, iia, iib)
    set_row(JW, j, UPPER, 0.0, 0.0, -1.0, -1.0, 0.0 if math.isnan(hi) else hi - ang, ims, iia, iib)


@row_inline
def point_rows(JW, j, a, b, ims, iia, iib):
    """EQ0, EQ1: the anchors' separation along x and y (n = e_x, e_y; ka = r_a x n)."""
    rax, ray, rbx, rby, dx, dy = arms(JW, j, a, b)
    set_row(JW, j, EQ0, 1.0, 0.0, -ray, -rby, dx, ims, iia, iib)
    set_row(JW, j, EQ1, 0.0, 1.0, rax, rbx, dy, ims, iia, iib)


@row_part
def rows_revolute(B, J, JW, j, a, b):
    """The point rows; the angular rows only where the joint has a spring, motor or limit (a
    plain hinge's refresh then writes two rows, not seven)."""
    ims = JW.SB[a, IM] + JW.SB[b, IM]
    iia = JW.SB[a, II]
    iib = JW.SB[b, II]
    point_rows(JW, j, a, b, ims, iia, iib)
    if not idle(J, JW, j, EQ2):
        clear_row(JW, j, EQ2)
    if not (idle(J, JW, j, SPRING) and idle(J, JW, j, MOTOR_ROW) and idle(J, JW, j, LOWER)
            and idle(J, JW, j, UPPER)):
        angular_rows(B, J, JW, j, ims, iia, iib)
