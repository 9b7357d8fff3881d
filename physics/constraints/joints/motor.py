"""Motor joint: drives a's origin to ``offset`` in b's frame and a's angle to b's + ``ref``,
with at most ``max_motor`` newtons and ``max_torque`` newton metres.

Rows EQ0, EQ1 (the separation of a's origin from the target point, as a
revolute's point rows) and EQ2 (the angle error) are velocity servos, each
pass removing CORRECTION of the error per pass span, with the accumulated
impulse clamped to a disc (force) and an interval (torque): Box2D v3.0's
motor_joint.c.  The correction is a drive, not drift removal, so it acts in
every pass.
"""
from __future__ import annotations

import math

from .jit import row_inline, row_part
from ...store.joints import EQ2, ROWS
from ..body_rows import II, IM
from .frame import relative_angle
from .layout import CC, MASS, MAX_MOTOR, MAX_TORQUE
from .revolute import point_rows
from .rows import apply_row, block_entry, clear_row, row_speed, set_row, solve_sym

CORRECTION = 0.3  # Box2D's default correction factor


@row_part
def prepare_motor(J, JW, j, h):
    JW.F[j, MAX_MOTOR] = J.max_motor[j] * h
    JW.F[j, MAX_TORQUE] = J.max_torque[j] * h
    return 0


@row_part
def rows_motor(B, J, JW, j, a, b):
    ims = JW.SB[a, IM] + JW.SB[b, IM]
    iia = JW.SB[a, II]
    iib = JW.SB[b, II]
    point_rows(JW, j, a, b, ims, iia, iib)
    set_row(JW, j, EQ2, 0.0, 0.0, 1.0, 1.0, relative_angle(B, J, j), ims, iia, iib)
    for r in range(EQ2 + 1, ROWS):
        clear_row(JW, j, r)


@row_inline
def clamp_disc(x, y, top):
    """(x, y) scaled onto the disc of radius ``top`` when outside it."""
    m = math.hypot(x, y)
    if m > top:
        s = top / m
        return x * s, y * s
    return x, y


@row_inline
def solve_motor_joint(J, JW, j, a, b, inv_h):
    bias = CORRECTION * inv_h
    # angular
    acc = J.impulse[j, 2]
    vn = row_speed(JW, a, b, j, 2) + bias * JW.G[j, 2, CC]
    top = JW.F[j, MAX_TORQUE]
    new = min(max(acc - JW.G[j, 2, MASS] * vn, -top), top)
    J.impulse[j, 2] = new
    apply_row(JW, a, b, j, 2, new - acc)
    # linear: both rows as a block, the accumulated impulse clamped to the force disc
    g0 = row_speed(JW, a, b, j, 0) + bias * JW.G[j, 0, CC]
    g1 = row_speed(JW, a, b, j, 1) + bias * JW.G[j, 1, CC]
    ok, x0, x1, _ = solve_sym(2, block_entry(JW, a, b, j, 0, 0), block_entry(JW, a, b, j, 0, 1), 0.0,
                              block_entry(JW, a, b, j, 1, 1), 0.0, 0.0, g0, g1, 0.0)
    if not ok:
        x0 = g0 * JW.G[j, 0, MASS]
        x1 = g1 * JW.G[j, 1, MASS]
    a0 = J.impulse[j, 0]
    a1 = J.impulse[j, 1]
    n0, n1 = clamp_disc(a0 - x0, a1 - x1, JW.F[j, MAX_MOTOR])
    J.impulse[j, 0] = n0
    J.impulse[j, 1] = n1
    apply_row(JW, a, b, j, 0, n0 - a0)
    apply_row(JW, a, b, j, 1, n1 - a1)
