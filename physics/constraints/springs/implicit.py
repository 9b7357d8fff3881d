"""All implicit springs of a (sub)step solved together: backward Euler on the spring network.

Each stiff spring is a soft constraint (Catto, "Soft Constraints", GDC 2011):
    gamma = 1 / (h (c + h k)),  bias = C h k gamma,
and backward Euler on the whole network is the linear system
    (J W J^T + Gamma) lambda = -(J v + bias)
(J the spring axes with their angular arms, W the inverse masses).  Solving
each spring alone, once, in sequence (one Gauss-Seidel sweep) is not that
system: along a chain of light links carrying a heavy load one sweep
transmits only a fraction of the load, so the chain behaves as a much softer
spring that stretches several times too far and swings with large true
elastic energy (1 kg links carrying 100 kg: +2e3 J over a 245 J drop).
The system is symmetric positive definite, so Jacobi-preconditioned
conjugate gradients (Hestenes & Stiefel 1952; Saad, "Iterative Methods for
Sparse Linear Systems", alg. 9.1) solve it exactly in at most one iteration
per spring; the product with J W J^T is matrix-free over the bodies.
Solved exactly, backward Euler on a spring network only removes energy.

Rows (per spring): ux, uy the axis; ra, rb the arms crossed with the axis;
diag = K + gamma; rhs; on (1: implicit row, 0: not in the system).
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel

ROW_FIELDS = 6  # ux, uy, ra_u, rb_u, diag, rhs
UX, UY, RA, RB, DIAG, RHS = range(ROW_FIELDS)
TOLERANCE = 1e-10  # relative residual at which the solve stops
MAX_ITERATIONS = 256


@kernel
def _impulses(B, S, ns, rows, on, lam, DV, DW):
    """DV, DW = W J^T lam: the velocity change of every touched body (others untouched)."""
    for s in range(ns):
        if on[s]:
            for i in (S.a[s], S.b[s]):
                if i >= 0:
                    DV[i, 0] = 0.0
                    DV[i, 1] = 0.0
                    DW[i] = 0.0
    for s in range(ns):
        if not on[s]:
            continue
        a = S.a[s]
        b = S.b[s]
        j = lam[s]
        DV[a, 0] -= B.inv_m[a] * j * rows[s, UX]
        DV[a, 1] -= B.inv_m[a] * j * rows[s, UY]
        DW[a] -= B.inv_i[a] * j * rows[s, RA]
        if b >= 0:
            DV[b, 0] += B.inv_m[b] * j * rows[s, UX]
            DV[b, 1] += B.inv_m[b] * j * rows[s, UY]
            DW[b] += B.inv_i[b] * j * rows[s, RB]


@kernel
def _product(B, S, ns, rows, on, gam, p, out, DV, DW):
    """out = (J W J^T + Gamma) p."""
    _impulses(B, S, ns, rows, on, p, DV, DW)
    for s in range(ns):
        if not on[s]:
            out[s] = 0.0
            continue
        a = S.a[s]
        b = S.b[s]
        v = -(DV[a, 0] * rows[s, UX] + DV[a, 1] * rows[s, UY]) - DW[a] * rows[s, RA]
        if b >= 0:
            v += DV[b, 0] * rows[s, UX] + DV[b, 1] * rows[s, UY] + DW[b] * rows[s, RB]
        out[s] = v + gam[s] * p[s]


@kernel
def solve_system(B, S, ns, rows, on, gam, lam):
    """Jacobi-preconditioned CG for lam (zero outside the system); returns the iterations used."""
    cap = B.inv_m.shape[0]
    DV = np.empty((cap, 2))
    DW = np.empty(cap)
    r = np.zeros(ns)
    z = np.zeros(ns)
    p = np.zeros(ns)
    q = np.zeros(ns)
    rz = 0.0
    bb = 0.0
    for s in range(ns):
        lam[s] = 0.0
        if on[s]:
            r[s] = rows[s, RHS]
            z[s] = r[s] / rows[s, DIAG]
            p[s] = z[s]
            rz += r[s] * z[s]
            bb += r[s] * r[s]
    if bb == 0.0:
        return 0
    limit = min(MAX_ITERATIONS, 2 * ns + 8)  # exact in ns steps; the rest absorbs round-off
    for it in range(limit):
        _product(B, S, ns, rows, on, gam, p, q, DV, DW)
        pq = 0.0
        for s in range(ns):
            pq += p[s] * q[s]
        if pq <= 0.0:
            return it
        alpha = rz / pq
        rr = 0.0
        rz_new = 0.0
        for s in range(ns):
            if on[s]:
                lam[s] += alpha * p[s]
                r[s] -= alpha * q[s]
                z[s] = r[s] / rows[s, DIAG]
                rr += r[s] * r[s]
                rz_new += r[s] * z[s]
        if rr <= TOLERANCE * TOLERANCE * bb:
            return it + 1
        beta = rz_new / rz
        rz = rz_new
        for s in range(ns):
            p[s] = z[s] + beta * p[s]
    return limit


@kernel
def apply_system(B, S, ns, rows, on, lam):
    """v += W J^T lam for the implicit springs."""
    for s in range(ns):
        if not on[s]:
            continue
        a = S.a[s]
        b = S.b[s]
        j = lam[s]
        B.v[a, 0] -= B.inv_m[a] * j * rows[s, UX]
        B.v[a, 1] -= B.inv_m[a] * j * rows[s, UY]
        B.w[a] -= B.inv_i[a] * j * rows[s, RA]
        if b >= 0:
            B.v[b, 0] += B.inv_m[b] * j * rows[s, UX]
            B.v[b, 1] += B.inv_m[b] * j * rows[s, UY]
            B.w[b] += B.inv_i[b] * j * rows[s, RB]
