"""Weld joint: a shared point and a fixed relative angle, each rigid or a spring.

Rows: EQ0, EQ1 the anchor separation (as the revolute's), EQ2 the relative
angle.  ``hertz`` softens the point rows, ``hertz2`` the angle row (0 = rigid),
``zeta`` damps both (Box2D v3's weld_joint.c linear/angular hertz).
"""
from __future__ import annotations

from .jit import row_part
from ...store.joints import EQ0, EQ1, EQ2, ROWS
from ..body_rows import II, IM
from .frame import relative_angle
from .revolute import point_rows
from .rows import clear_row, set_row
from .soft_rows import spring_row


@row_part
def prepare_weld(J, JW, j, h):
    spring_row(JW, j, 0, J.hertz[j], J.zeta[j], h)
    spring_row(JW, j, 1, J.hertz[j], J.zeta[j], h)
    spring_row(JW, j, 2, J.hertz2[j], J.zeta[j], h)
    return (1 << EQ0) | (1 << EQ1) | (1 << EQ2)


@row_part
def rows_weld(B, J, JW, j, a, b):
    ims = JW.SB[a, IM] + JW.SB[b, IM]
    iia = JW.SB[a, II]
    iib = JW.SB[b, II]
    point_rows(JW, j, a, b, ims, iia, iib)
    set_row(JW, j, EQ2, 0.0, 0.0, 1.0, 1.0, relative_angle(B, J, j), ims, iia, iib)
    for r in range(EQ2 + 1, ROWS):
        clear_row(JW, j, r)
