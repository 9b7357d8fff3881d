"""A structure of one joint: its 1-3 equality rows solved as the global system solves them, in place.

The global passes (solve.py) assemble, factor and solve one sparse system per pass; for a joint
that shares no moving body with another (a pendulum, each wire of a cradle) that system is the
joint's own block, and the sparse machinery around it cost more than the block.  topology.py
leaves such a joint out of the system (``seq`` BLOCK) and the passes solve its block here with
the same arithmetic: the entries summed body by body as ``assemble`` sums them, the same
right-hand sides and compliances, and the up-looking LDL^T of ldl.py written out for a dense
block of at most three rows (the same operations in the same order, the same dropped pivots).
So the numbers are those of the global path, bit for bit, and a world of lone joints needs no
system at all.  The blocks are solved after every joint's free rows, where the system is.
"""
from __future__ import annotations

from ..jit import row_inline, row_part
from ..layout import CC, KA, KB, NX, NY, SOFT_EQ
from ..rows import apply_row, row_speed
from ..shift import capped_error, shift_row
from ...body_rows import II, IM
from .ldl import DROP

#: ``seq`` per joint (topology.py): its rows in the system, solved one joint at a time (a structure
#: that would fill the factor too much), or its block solved here
SYSTEM, SEQUENTIAL, BLOCK = 0, 1, 2


@row_inline
def entry(JW, a, b, j, r, s, skipped):
    """K_rs as ``assemble`` sums it: a's contribution, then b's (a body that cannot move adds 0);
    a row that sits out is an identity row."""
    if skipped:
        return 1.0 if r == s else 0.0
    G = JW.G
    SB = JW.SB
    nn = G[j, r, NX] * G[j, s, NX] + G[j, r, NY] * G[j, s, NY]
    k = 0.0 + (SB[a, IM] * nn + SB[a, II] * G[j, r, KA] * G[j, s, KA])
    return k + (SB[b, IM] * nn + SB[b, II] * G[j, r, KB] * G[j, s, KB])


@row_inline
def pivot(d, a):
    """ldl.numeric's inverse pivot: 0 for a pivot below DROP times its diagonal."""
    return 1.0 / d if d > DROP * a and d > 0.0 else 0.0


@row_inline
def ldl_solve(m, k00, k01, k02, k11, k12, k22, x0, x1, x2):
    """K^-1 x for the leading m x m part of K (upper entries), by ldl.numeric and ldl.solve's
    operations on a dense pattern in row order."""
    i0 = pivot(k00, k00)
    l10 = l20 = l21 = 0.0
    i1 = i2 = 0.0
    if m > 1:
        l10 = k01 * i0
        i1 = pivot(k11 - l10 * k01, k11)
    if m > 2:  # column 2: row 0's entry, then row 1's after column 0's update
        y1 = k12 - l10 * k02
        l20 = k02 * i0
        l21 = y1 * i1
        i2 = pivot((k22 - l20 * k02) - l21 * y1, k22)
    if x0 != 0.0:  # forward: L y = x, column by column
        x1 -= l10 * x0
        x2 -= l20 * x0
    if m > 2 and x1 != 0.0:
        x2 -= l21 * x1
    x0 *= i0
    x1 *= i1
    x2 *= i2
    x1 = x1 - l21 * x2  # backward: L^T x = y
    x0 = (x0 - l10 * x1) - l20 * x2
    return x0, x1, x2


@row_inline
def block_matrix(JW, a, b, j, m, s0, s1, s2):
    """The block's upper entries (rows flagged s_r sit out: identity rows)."""
    k00 = entry(JW, a, b, j, 0, 0, s0)
    k01 = k02 = k11 = k12 = k22 = 0.0
    if m > 1:
        k01 = entry(JW, a, b, j, 0, 1, s0 or s1)
        k11 = entry(JW, a, b, j, 1, 1, s1)
    if m > 2:
        k02 = entry(JW, a, b, j, 0, 2, s0 or s2)
        k12 = entry(JW, a, b, j, 1, 2, s1 or s2)
        k22 = entry(JW, a, b, j, 2, 2, s2)
    return k00, k01, k02, k11, k12, k22


@row_inline
def rhs(J, JW, a, b, j, r, kd, use_bias):
    """(right-hand side, diagonal) of row r in a velocity pass, as solve_system makes them: a
    spring row adds its compliance to the diagonal."""
    F = JW.F
    o = SOFT_EQ + 6 * r
    g = row_speed(JW, a, b, j, r)
    if F[j, o + 5] > 0.0:
        gam = kd * F[j, o + 5] / F[j, o + 4]
        return -(g + F[j, o + 3] * JW.G[j, r, CC] + gam * J.impulse[j, r]), kd + gam
    if use_bias:
        return -(g + F[j, o] * JW.G[j, r, CC]), kd
    return -g, kd


@row_inline
def solve_block(J, JW, j, a, b, m, use_bias):
    """One velocity pass over the joint's m equality rows (biased, or relax)."""
    no = False
    k00, k01, k02, k11, k12, k22 = block_matrix(JW, a, b, j, m, no, no, no)
    x0, k00 = rhs(J, JW, a, b, j, 0, k00, use_bias)
    x1 = x2 = 0.0
    if m > 1:
        x1, k11 = rhs(J, JW, a, b, j, 1, k11, use_bias)
    if m > 2:
        x2, k22 = rhs(J, JW, a, b, j, 2, k22, use_bias)
    x0, x1, x2 = ldl_solve(m, k00, k01, k02, k11, k12, k22, x0, x1, x2)
    for r in range(m):
        lam = x0 if r == 0 else (x1 if r == 1 else x2)
        J.impulse[j, r] += lam
        apply_row(JW, a, b, j, r, lam)


@row_inline
def spring_row(JW, j, r):
    return JW.F[j, SOFT_EQ + 6 * r + 5] > 0.0


@row_part
def correct_block(B, JW, j, a, b, m):
    """One position pass (a Newton step, as correct_system with beta 1): the rigid rows' capped
    errors removed at once; spring rows sit out."""
    s0 = spring_row(JW, j, 0)
    s1 = m > 1 and spring_row(JW, j, 1)
    s2 = m > 2 and spring_row(JW, j, 2)
    k00, k01, k02, k11, k12, k22 = block_matrix(JW, a, b, j, m, s0, s1, s2)
    G = JW.G
    x0 = 0.0 if s0 else -capped_error(JW, j, 0, G[j, 0, CC])
    x1 = 0.0 if s1 or m < 2 else -capped_error(JW, j, 1, G[j, 1, CC])
    x2 = 0.0 if s2 or m < 3 else -capped_error(JW, j, 2, G[j, 2, CC])
    x0, x1, x2 = ldl_solve(m, k00, k01, k02, k11, k12, k22, x0, x1, x2)
    for r in range(m):
        if not (s0 if r == 0 else (s1 if r == 1 else s2)):
            shift_row(B, JW, a, b, j, r, x0 if r == 0 else (x1 if r == 1 else x2))
