"""Rotary joint: nothing but the relative angle q_a - q_b - ref, with an angular spring, a motor
and angle limits, and no point held (pymunk's DampedRotarySpring, SimpleMotor and
RotaryLimitJoint in one; the revolute joint's angular rows without its point rows).

Rows (store/joints.py): no equality rows; the spring, motor and limit rows are the revolute's.
"""
from __future__ import annotations

from ...store.joints import CODE, EQ0, EQ1, EQ2
from ..body_rows import II, IM
from .jit import row_part
from .revolute import angular_prepare, angular_rows
from .rows import clear_row

ROTARY = CODE["rotary"]


@row_part
def prepare_rotary(J, JW, j, h):
    """Softness and clamps for one step; returns the row mask (spring, motor, limits only)."""
    return angular_prepare(J, JW, j, h, 0)


@row_part
def rows_rotary(B, J, JW, j, a, b):
    ims = JW.SB[a, IM] + JW.SB[b, IM]
    iia = JW.SB[a, II]
    iib = JW.SB[b, II]
    clear_row(JW, j, EQ0)
    clear_row(JW, j, EQ1)
    clear_row(JW, j, EQ2)
    angular_rows(B, J, JW, j, ims, iia, iib)
