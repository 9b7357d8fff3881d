"""Position correction of the joints by non-linear Gauss-Seidel (sequential_impulse, classic).

Modes that do not sub-step with a relax pass correct joint drift on the
positions after they moved (Catto, Box2D 2.x b2SolvePositionConstraints; NGS
in "Solver2D", 2024): each pass measures every row's position error at the
current positions and moves the bodies along the row by -beta C / K, capped per
correction (shift.py).  The equality rows of a structure in the global system
are one Newton step on all its joint equations at once (beta = 1,
dispatch.py ``correct_structures``); sequential rows and the limits (only where
violated) take ``beta`` of their error per pass.  Springs are left alone.
"""
from __future__ import annotations

import numpy as np

from ...store.joints import LOWER, MOTOR, MOUSE, UPPER
from .dispatch import correct_structures, equality_rows_of, joint_rows
from .jit import row_inline, row_kernel, row_part
from .layout import CC, MASS, SOFT_EQ
from .rows import block_entry, solve_sym
from .shift import capped_error, shift_row
from .sync import displacement_from_table
from .system.block import SEQUENTIAL


@row_inline
def rigid_error(JW, j, r, m):
    """Row r's capped position error if it is a rigid equality row of the block, else 0."""
    if r >= m or JW.F[j, SOFT_EQ + 6 * r + 5] != 0.0:
        return 0.0
    return capped_error(JW, j, r, JW.G[j, r, CC])


@row_part
def correct_equality(B, J, JW, j, a, b, m, beta):
    """The joint's rigid equality rows as one block at the position level."""
    g0 = rigid_error(JW, j, 0, m)
    g1 = rigid_error(JW, j, 1, m)
    g2 = rigid_error(JW, j, 2, m)
    ok, x0, x1, x2 = solve_sym(m, block_entry(JW, a, b, j, 0, 0),
                               block_entry(JW, a, b, j, 0, 1) if m > 1 else 0.0,
                               block_entry(JW, a, b, j, 0, 2) if m > 2 else 0.0,
                               block_entry(JW, a, b, j, 1, 1) if m > 1 else 0.0,
                               block_entry(JW, a, b, j, 1, 2) if m > 2 else 0.0,
                               block_entry(JW, a, b, j, 2, 2) if m > 2 else 0.0, g0, g1, g2)
    if not ok:
        x0 = g0 * JW.G[j, 0, MASS]
        x1 = g1 * JW.G[j, 1, MASS]
        x2 = g2 * JW.G[j, 2, MASS]
    for r in range(m):
        x = x0 if r == 0 else (x1 if r == 1 else x2)
        if x != 0.0:
            shift_row(B, JW, a, b, j, r, -beta * x)


@row_part
def correct_limit(B, JW, a, b, j, r, beta):
    c = JW.G[j, r, CC]
    if c < 0.0:
        shift_row(B, JW, a, b, j, r, -beta * JW.G[j, r, MASS] * capped_error(JW, j, r, c))


@row_kernel
def correct_joint_positions(c, B, J, JW, JS, eq_global, beta, iterations):
    """``iterations`` position passes over the joints (see the module doc)."""
    for _ in range(iterations):
        displacement_from_table(B, c.n, JW)
        for j in range(c.nj):
            if not JW.on[j]:
                continue
            kind = J.kind[j]
            if kind == MOTOR or kind == MOUSE:
                continue
            a = JW.ab[j, 0]
            b = JW.ab[j, 1]
            joint_rows(B, J, JW, j, a, b)
            mask = JW.mask[j]
            m = equality_rows_of(mask)
            if m > 0 and (not eq_global or JW.seq[j] == SEQUENTIAL):
                correct_equality(B, J, JW, j, a, b, m, beta)
            if mask & (1 << LOWER):
                correct_limit(B, JW, a, b, j, np.int64(LOWER), beta)
            if mask & (1 << UPPER):
                correct_limit(B, JW, a, b, j, np.int64(UPPER), beta)
        if eq_global:
            correct_structures(c, B, JW, JS)
