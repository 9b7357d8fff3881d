"""Sparse LDL^T of a symmetric matrix in compressed columns (upper part given).

The up-looking algorithm of Davis's LDL package ("Algorithm 849", ACM TOMS 31,
2005; "Direct Methods for Sparse Linear Systems", 2006, sec. 4.1-4.5): the
elimination tree (``Parent``) and the column counts of L come from the pattern
once (``symbolic``); each factorisation computes row k of L by a sparse
triangular solve whose pattern is the etree reach of A's column k.

Dependent rows (a closed loop whose joints over-constrain it, two joints
holding the same thing) make pivots vanish.  A pivot below DROP times its
original diagonal is dropped: its inverse is taken as 0, so that direction of
the solution is 0 and the remaining rows are solved exactly (what a rank-
revealing factorisation would do for a consistent system).
"""
from __future__ import annotations

from ..jit import row_entry, row_kernel

DROP = 1e-9


@row_entry
def symbolic(nr, Ap, Ai, Parent, Lnz, Flag, Lp):
    """Elimination tree and column pointers of L for the pattern (Ap, Ai): entries i <= k of column k."""
    for k in range(nr):
        Parent[k] = -1
        Flag[k] = k
        Lnz[k] = 0
        for p in range(Ap[k], Ap[k + 1]):
            i = Ai[p]
            if i < k:
                while Flag[i] != k:
                    if Parent[i] == -1:
                        Parent[i] = k
                    Lnz[i] += 1
                    Flag[i] = k
                    i = Parent[i]
    Lp[0] = 0
    for k in range(nr):
        Lp[k + 1] = Lp[k] + Lnz[k]


@row_kernel
def numeric(nr, Ap, Ai, Ax, Lp, Parent, Lnz, Li, Lx, invD, Y, Pattern, Flag):
    """L (unit lower, by columns) and D^-1 of A = L D L^T; returns the number of dropped pivots."""
    dropped = 0
    for k in range(nr):
        Y[k] = 0.0
        top = nr
        Flag[k] = k
        Lnz[k] = 0
        for p in range(Ap[k], Ap[k + 1]):
            i = Ai[p]
            Y[i] += Ax[p]
            ln = 0
            while Flag[i] != k:
                Pattern[ln] = i
                ln += 1
                Flag[i] = k
                i = Parent[i]
            while ln > 0:
                top -= 1
                ln -= 1
                Pattern[top] = Pattern[ln]
        akk = Y[k]
        dk = akk
        Y[k] = 0.0
        for t in range(top, nr):
            i = Pattern[t]
            yi = Y[i]
            Y[i] = 0.0
            p2 = Lp[i] + Lnz[i]
            for p in range(Lp[i], p2):
                Y[Li[p]] -= Lx[p] * yi
            lki = yi * invD[i]
            dk -= lki * yi
            Li[p2] = k
            Lx[p2] = lki
            Lnz[i] += 1
        if dk > DROP * akk and dk > 0.0:
            invD[k] = 1.0 / dk
        else:
            invD[k] = 0.0
            dropped += 1
    return dropped


@row_kernel
def solve(nr, Lp, Lnz, Li, Lx, invD, x):
    """x <- A^-1 x with the factors (forward, diagonal, backward)."""
    for j in range(nr):
        xj = x[j]
        if xj != 0.0:
            for p in range(Lp[j], Lp[j] + Lnz[j]):
                x[Li[p]] -= Lx[p] * xj
    for j in range(nr):
        x[j] *= invD[j]
    for j in range(nr - 1, -1, -1):
        s = x[j]
        for p in range(Lp[j], Lp[j] + Lnz[j]):
            s -= Lx[p] * x[Li[p]]
        x[j] = s
