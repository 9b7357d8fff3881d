"""Wheel joint: a point on a line fixed in a (the chassis), sprung along it, free to turn.

Rows: EQ0 keeps b's anchor on a's axis (as the prismatic's); the spring and the
limits act on the translation along the axis (the suspension), the motor on the
relative angular speed w_a - w_b (Box2D v3's wheel_joint.c, with a's rotation
relative to b's as everywhere here).
"""
from __future__ import annotations

from .jit import row_part
from ...store.joints import EQ0, EQ1, EQ2, MOTOR_ROW
from ..body_rows import II, IM
from .layout import MAX_MOTOR
from .prismatic import axial_prepare, slide_rows
from .rows import clear_row, set_row
from .soft_rows import rigid_row


@row_part
def prepare_wheel(J, JW, j, h):
    rigid_row(JW, j, 0)
    mask = axial_prepare(J, JW, j, h, 1 << EQ0)
    if J.max_motor[j] > 0.0:
        JW.F[j, MAX_MOTOR] = J.max_motor[j] * h
        mask |= 1 << MOTOR_ROW
    return mask


@row_part
def rows_wheel(B, J, JW, j, a, b):
    ims = JW.SB[a, IM] + JW.SB[b, IM]
    iia = JW.SB[a, II]
    iib = JW.SB[b, II]
    slide_rows(J, JW, j, a, b, ims, iia, iib, False)
    set_row(JW, j, MOTOR_ROW, 0.0, 0.0, 1.0, 1.0, 0.0, ims, iia, iib)
    clear_row(JW, j, EQ1)
    clear_row(JW, j, EQ2)
