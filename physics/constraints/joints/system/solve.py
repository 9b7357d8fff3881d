"""The global passes: assemble (J M^-1 J^T + Gamma) from the joints' rows, factor, solve, apply.

Entry e of the matrix is the sum of its contributions (topology.py): for joint
rows (j, r) and (k, s) sharing a moving body c,
    s_j s_k (m_c^-1 n_jr . n_ks + I_c^-1 k_jr k_ks),
with s = +1 on a joint's body a and -1 on b and k its ka or kb.  Rigid rows solve
    K dlam = -(C' + bias C)     (bias: the mode's joint bias rate, none when relaxing),
and rows that are springs on purpose add their compliance gamma = K_rr is / ms
(constraints/softness.py; the same fixed point as Box2D's soft row):
    (K + gamma) dlam = -(C' + rate C + gamma lam).
The position pass solves K dlam = -beta C on the positions (a Newton step on the
joint equations when beta = 1) and leaves springs alone.  Rows of joints that
are off this step (asleep, broken) are decoupled (identity rows).

The velocity passes' matrix depends only on the rows' geometry (refreshed once per move,
dispatch.refresh_rows), the bodies' inverse masses and the rows taking part, all fixed between
two moves; so it is assembled and factored once per move and its factors serve every velocity
pass until the next (``dims[FACTORED]``; refresh_rows and the position pass mark them stale).
A soft step solves twice per move (relax, then the next sub-step's solve) and a sequential
impulse step once per velocity iteration on one set of rows: the same numbers, fewer factorisations.
"""
from __future__ import annotations

import numpy as np

from ...body_rows import II, IM
from ..jit import row_inline, row_kernel
from ..layout import CC, KA, KB, NX, NY, SOFT_EQ
from ..rows import apply_row, row_speed
from ..shift import capped_error, shift_row
from . import ldl

#: dims[FACTORED]: STALE (assemble and factor at the next velocity pass), READY (L and invD hold the
#: factors of the velocity passes' matrix, gam the spring rows' compliances), or IDLE (every row
#: sits out until the rows change)
FACTORED = 4
STALE, READY, IDLE = 0, 1, 2


@row_inline
def mark_skips(JW, JS, positions):
    """Which rows sit out this pass: (whether any row takes part, whether any sits out)."""
    active = False
    idle = False
    row_j, row_r, skips = JS.row_j, JS.row_r, JS.skip  # (each field's view made once: store/segments.py)
    for i in range(JS.dims[0]):
        j = row_j[i]
        skip = JW.on[j] == 0
        if not skip and positions and JW.F[j, SOFT_EQ + 6 * row_r[i] + 5] > 0.0:
            skip = True  # a spring row is not projected onto its rest position
        skips[i] = skip
        active |= not skip
        idle |= skip
    return active, idle


@row_inline
def assemble(JW, JS, idle):
    """Ax from the rows' Jacobians; skipped rows (``idle``: there are some) become identity rows."""
    G = JW.G
    SB = JW.SB
    Ax = JS.Ax
    for e in range(JS.dims[2]):
        Ax[e] = 0.0
    Q = JS.contrib
    skip, jrow, Ap = JS.skip, JS.jrow, JS.Ap
    for q in range(JS.dims[1]):
        j = Q[q, 2]
        r = Q[q, 3]
        k = Q[q, 5]
        s = Q[q, 6]
        if idle and (skip[jrow[j] + r] or skip[jrow[k] + s]):
            continue
        c = Q[q, 1]
        sj = Q[q, 4]
        sk = Q[q, 7]
        kj = G[j, r, KA] if sj > 0 else G[j, r, KB]
        kk = G[k, s, KA] if sk > 0 else G[k, s, KB]
        Ax[Q[q, 0]] += sj * sk * (SB[c, IM] * (G[j, r, NX] * G[k, s, NX] + G[j, r, NY] * G[k, s, NY])
                                  + SB[c, II] * kj * kk)
    for i in range(JS.dims[0] if idle else 0):
        if skip[i]:
            Ax[Ap[i + 1] - 1] = 1.0  # the diagonal is the last entry of its column


@row_inline
def factor_and_solve(JS):
    nr = JS.dims[0]
    ldl.numeric(nr, JS.Ap, JS.Ai, JS.Ax, JS.Lp, JS.Parent, JS.Lnz, JS.Li, JS.Lx, JS.invD, JS.Y, JS.Pattern,
                JS.Flag)
    ldl.solve(nr, JS.Lp, JS.Lnz, JS.Li, JS.Lx, JS.invD, JS.x)


@row_kernel
def solve_system(J, JW, JS, use_bias):
    """One velocity pass over all global equality rows (biased, or relax), on the factors of the
    last pass when the rows did not change since (module doc)."""
    state = JS.dims[FACTORED]
    if state == IDLE:
        return
    if state == STALE:
        active, idle = mark_skips(JW, JS, np.bool_(False))
        if not active:
            JS.dims[FACTORED] = IDLE
            return
        assemble(JW, JS, idle)
    G = JW.G
    F = JW.F
    skip, row_j, row_r, x, Ap, Ax, gams = JS.skip, JS.row_j, JS.row_r, JS.x, JS.Ap, JS.Ax, JS.gam
    for i in range(JS.dims[0]):
        if skip[i]:
            x[i] = 0.0
            continue
        j = row_j[i]
        r = row_r[i]
        o = SOFT_EQ + 6 * r
        g = row_speed(JW, JW.ab[j, 0], JW.ab[j, 1], j, r)
        if F[j, o + 5] > 0.0:
            if state == STALE:
                d = Ap[i + 1] - 1
                gams[i] = Ax[d] * F[j, o + 5] / F[j, o + 4]
                Ax[d] += gams[i]
            gam = gams[i]
            x[i] = -(g + F[j, o + 3] * G[j, r, CC] + gam * J.impulse[j, r])
        elif use_bias:
            x[i] = -(g + F[j, o] * G[j, r, CC])
        else:
            x[i] = -g
    if state == STALE:
        factor_and_solve(JS)
        JS.dims[FACTORED] = READY
    else:
        ldl.solve(JS.dims[0], JS.Lp, JS.Lnz, JS.Li, JS.Lx, JS.invD, JS.x)
    for i in range(JS.dims[0]):
        if not skip[i]:
            j = row_j[i]
            r = row_r[i]
            lam = x[i]
            J.impulse[j, r] += lam
            apply_row(JW, JW.ab[j, 0], JW.ab[j, 1], j, r, lam)


@row_kernel
def correct_system(B, JW, JS, beta):
    """One position pass: K dlam = -beta C (errors capped per row), applied to the positions.  Its
    matrix (springs left out) replaces the velocity passes' factors: they are stale after it."""
    JS.dims[FACTORED] = STALE
    active, idle = mark_skips(JW, JS, np.bool_(True))
    if not active:
        return
    assemble(JW, JS, idle)
    G = JW.G
    skip, row_j, row_r, x = JS.skip, JS.row_j, JS.row_r, JS.x
    for i in range(JS.dims[0]):
        if skip[i]:
            x[i] = 0.0
        else:
            j = row_j[i]
            r = row_r[i]
            x[i] = -beta * capped_error(JW, j, r, G[j, r, CC])
    factor_and_solve(JS)
    for i in range(JS.dims[0]):
        if not skip[i]:
            j = row_j[i]
            shift_row(B, JW, JW.ab[j, 0], JW.ab[j, 1], j, row_r[i], x[i])
