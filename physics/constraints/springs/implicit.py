"""All implicit spring rows of a (sub)step solved together: backward Euler on the spring network.

Each stiff spring is a soft constraint (Catto, "Soft Constraints", GDC 2011):
    gamma = 1 / (h (c + h k)),  bias = C h k gamma,
and backward Euler on the whole network is the linear system
    (J W J^T + Gamma) lambda = -(J v + bias)
(J the rows' Jacobians, W the inverse masses).  Solving each spring alone,
once, in sequence (one Gauss-Seidel sweep) is not that system: along a chain
of light links carrying a heavy load one sweep transmits only a fraction of
the load, so the chain behaves as a much softer spring that stretches several
times too far and swings with large true elastic energy (1 kg links carrying
100 kg: +2e3 J over a 245 J drop).  The system is symmetric positive definite,
so Jacobi-preconditioned conjugate gradients (Hestenes & Stiefel 1952; Saad,
"Iterative Methods for Sparse Linear Systems", alg. 9.1) solve it exactly in at
most one iteration per row; the product with J W J^T is matrix-free over the
bodies.  Solved exactly, backward Euler with a positive semi-definite stiffness
only removes energy.

A row is general: body ``a`` with Jacobian (JAX, JAY, JAW), body ``b`` (-1: none)
with (JBX, JBY, JBW), so that dC/dt = J_a . (v_a, w_a) + J_b . (v_b, w_b); DIAG
is J W J^T + gamma (the preconditioner) and RHS the right-hand side.  Besides a
spring's axis the rows carry its geometric stiffness (geometric.py).
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel

ROW_FIELDS = 8
JAX, JAY, JAW, JBX, JBY, JBW, DIAG, RHS = range(ROW_FIELDS)
TOLERANCE = 1e-10  # relative residual at which the solve stops
MAX_ITERATIONS = 256


@kernel
def row_mass(B, rows, bod, r):
    """J W J^T of row r (the inverse effective mass along it)."""
    a = bod[r, 0]
    b = bod[r, 1]
    k = B.inv_m[a] * (rows[r, JAX] ** 2 + rows[r, JAY] ** 2) + B.inv_i[a] * rows[r, JAW] ** 2
    if b >= 0:
        k += B.inv_m[b] * (rows[r, JBX] ** 2 + rows[r, JBY] ** 2) + B.inv_i[b] * rows[r, JBW] ** 2
    return k


@kernel
def row_speed(V, W, rows, bod, r):
    """J v of row r for velocities (V, W)."""
    a = bod[r, 0]
    b = bod[r, 1]
    v = V[a, 0] * rows[r, JAX] + V[a, 1] * rows[r, JAY] + W[a] * rows[r, JAW]
    if b >= 0:
        v += V[b, 0] * rows[r, JBX] + V[b, 1] * rows[r, JBY] + W[b] * rows[r, JBW]
    return v


@kernel
def add_impulse(B, V, W, rows, bod, r, j):
    """(V, W) += W_body J_r^T j."""
    a = bod[r, 0]
    b = bod[r, 1]
    V[a, 0] += B.inv_m[a] * j * rows[r, JAX]
    V[a, 1] += B.inv_m[a] * j * rows[r, JAY]
    W[a] += B.inv_i[a] * j * rows[r, JAW]
    if b >= 0:
        V[b, 0] += B.inv_m[b] * j * rows[r, JBX]
        V[b, 1] += B.inv_m[b] * j * rows[r, JBY]
        W[b] += B.inv_i[b] * j * rows[r, JBW]


@kernel
def _product(B, nr, rows, bod, gam, p, out, DV, DW):
    """out = (J W J^T + Gamma) p (DV, DW: scratch, zeroed at the touched bodies)."""
    for r in range(nr):
        for i in (bod[r, 0], bod[r, 1]):
            if i >= 0:
                DV[i, 0] = 0.0
                DV[i, 1] = 0.0
                DW[i] = 0.0
    for r in range(nr):
        add_impulse(B, DV, DW, rows, bod, r, p[r])
    for r in range(nr):
        out[r] = row_speed(DV, DW, rows, bod, r) + gam[r] * p[r]


@kernel(runtime=True)
def solve_system(B, nr, rows, bod, gam, lam):
    """Jacobi-preconditioned CG for lam over the first nr rows; returns the iterations used."""
    cap = B.inv_m.shape[0]
    DV = np.empty((cap, 2))
    DW = np.empty(cap)
    r = np.zeros(nr)
    z = np.zeros(nr)
    p = np.zeros(nr)
    q = np.zeros(nr)
    rz = 0.0
    bb = 0.0
    for s in range(nr):
        lam[s] = 0.0
        r[s] = rows[s, RHS]
        z[s] = r[s] / rows[s, DIAG]
        p[s] = z[s]
        rz += r[s] * z[s]
        bb += r[s] * r[s]
    if bb == 0.0:
        return 0
    limit = min(MAX_ITERATIONS, 2 * nr + 8)  # exact in nr steps; the rest absorbs round-off
    for it in range(limit):
        _product(B, nr, rows, bod, gam, p, q, DV, DW)
        pq = 0.0
        for s in range(nr):
            pq += p[s] * q[s]
        if not pq > 0.0:  # converged to round-off (or nan: the finite check reports it)
            return it
        alpha = rz / pq
        rr = 0.0
        rz_new = 0.0
        for s in range(nr):
            lam[s] += alpha * p[s]
            r[s] -= alpha * q[s]
            z[s] = r[s] / rows[s, DIAG]
            rr += r[s] * r[s]
            rz_new += r[s] * z[s]
        if rr <= TOLERANCE * TOLERANCE * bb:
            return it + 1
        beta = rz_new / rz
        rz = rz_new
        for s in range(nr):
            p[s] = z[s] + beta * p[s]
    return limit


@kernel
def apply_system(B, nr, rows, bod, lam):
    """v += W J^T lam over the first nr rows."""
    for r in range(nr):
        add_impulse(B, B.v, B.w, rows, bod, r, lam[r])
