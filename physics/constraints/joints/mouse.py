"""Mouse joint: a soft spring from a point of body a (``la``) to a world target (``lb``).

Rows EQ0, EQ1 as the revolute's point rows; solved as one soft block of the
joint's own frequency and damping ratio in every pass, the accumulated impulse
clamped to ``max_motor`` newtons (Box2D v3's mouse_joint.c).  Assigning the
target moves ``lb``; the sandbox drags bodies with it.
"""
from __future__ import annotations

from .jit import row_inline, row_part
from ...store.joints import EQ1, ROWS
from ..body_rows import II, IM
from .layout import CC, MASS, MAX_MOTOR, SOFT_SPRING
from .motor import clamp_disc
from .revolute import point_rows
from .rows import apply_row, block_entry, clear_row, row_speed, solve_sym
from .soft_rows import spring_softness


@row_part
def prepare_mouse(J, JW, j, h):
    spring_softness(JW, j, J.hertz[j], J.zeta[j], h)
    JW.F[j, MAX_MOTOR] = J.max_motor[j] * h
    return 0


@row_part
def rows_mouse(B, J, JW, j, a, b):
    ims = JW.SB[a, IM] + JW.SB[b, IM]
    point_rows(JW, j, a, b, ims, JW.SB[a, II], JW.SB[b, II])
    for r in range(EQ1 + 1, ROWS):
        clear_row(JW, j, r)


@row_inline
def solve_mouse(J, JW, j, a, b):
    rate = JW.F[j, SOFT_SPRING]
    ms = JW.F[j, SOFT_SPRING + 1]
    isc = JW.F[j, SOFT_SPRING + 2]
    g0 = row_speed(JW, a, b, j, 0) + rate * JW.G[j, 0, CC]
    g1 = row_speed(JW, a, b, j, 1) + rate * JW.G[j, 1, CC]
    ok, x0, x1, _ = solve_sym(2, block_entry(JW, a, b, j, 0, 0), block_entry(JW, a, b, j, 0, 1), 0.0,
                              block_entry(JW, a, b, j, 1, 1), 0.0, 0.0, g0, g1, 0.0)
    if not ok:
        x0 = g0 * JW.G[j, 0, MASS]
        x1 = g1 * JW.G[j, 1, MASS]
    a0 = J.impulse[j, 0]
    a1 = J.impulse[j, 1]
    n0, n1 = clamp_disc(a0 - ms * x0 - isc * a0, a1 - ms * x1 - isc * a1, JW.F[j, MAX_MOTOR])
    J.impulse[j, 0] = n0
    J.impulse[j, 1] = n1
    apply_row(JW, a, b, j, 0, n0 - a0)
    apply_row(JW, a, b, j, 1, n1 - a1)
