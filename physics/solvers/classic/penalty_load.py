"""Keep penalty contacts stable when several points load one body (issue 20 item 2).

The sub-step count (common.contact_rate) makes omega h small enough for ONE penalty point:
its spring and damper act on the point's effective mass m_i = 1/(J_i M^-1 J_i^T), so alone
it rings at omega.  Several points on one body add up: the system's stiffness is
K = sum_i k_i J_i^T J_i with k_i = m_i omega^2 (the damping likewise, c_i = 2 zeta omega m_i),
and its fastest mode is omega^2 lambda_max with lambda_max the largest eigenvalue of the points'
Gram matrix G_ij = sqrt(m_i m_j) J_i M^-1 J_j^T (unit diagonal).  Two overlapping fixtures of
one compound body touching the same neighbour give two identical points (G_ij = 1), four give
lambda = 4: symplectic Euler then diverges (Box2D's compounds scene blew up within 2 s).

Symplectic Euler on x'' = -lambda (omega^2 x + 2 zeta omega x') with u = omega h is stable iff
lambda (u^2 + 4 zeta u) < 4 (Jury's test on its 2x2 step matrix: det = 1 - 2 zeta lambda u,
trace = 2 - lambda u^2 - 2 zeta lambda u).  That is the bound of a two-sided spring; a contact
only pushes (F_n >= 0 cuts off the half-cycle in which an overshooting damper would pull), and
measured, it holds to about twice that: the shipped pyramid runs stable at lambda = 4.5, 1.8
times the bound (8 sub-steps at 60 Hz, contact 25 Hz, zeta 1); the compounds scene diverged at
lambda = 9 to 17, 3.5 to 7 times it, and ran stable at 3x the sub-steps (1.3 to 2.1 times).
``stable_load`` is 0.9 of twice the bound for the step's u.  Per step, ``scale_penalty_points`` estimates lambda_max by power iteration on G
(matrix-free: G x = D^1/2 J M^-1 J^T D^1/2 x through per-body sums, O(points) per iteration;
the Rayleigh quotient after ITERATIONS products).  Where it exceeds the limit T every penalty
point's stiffness and damping are scaled by T / lambda_max, which puts the fastest mode at the
limit; a world within the limit (a box on the ground: lambda = 1.2; the shipped pyramid) keeps
s = 1 exactly and behaves as before.  (Gershgorin's row sums would bound lambda without
iterating, but they over-estimate a pyramid's 2 to 3 fold and would soften every stack.)
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from .contact_geometry import PENALTY


def stable_load(omega: float, zeta: float, h: float) -> float:
    """0.9 of twice the largest lambda for which symplectic Euler keeps a two-sided damped
    spring stable at u = omega h (one-sided contact holds to about twice it: module doc)."""
    u = omega * h
    den = u * u + 4.0 * zeta * u
    return 0.9 * 2.0 * 4.0 / den if den > 0.0 else math.inf


ITERATIONS = 40


@kernel
def _row(C, P, k, p, x):
    """(+1 if x is body b else -1, r x n) of point (k, p)'s row on body x: J = sign (n, r x n)."""
    if C.a[k] == x:
        return -1.0, P.ra[k, p, 0] * C.normal[k, 1] - P.ra[k, p, 1] * C.normal[k, 0]
    return 1.0, P.rb[k, p, 0] * C.normal[k, 1] - P.rb[k, p, 1] * C.normal[k, 0]


@kernel
def _gram_product(B, C, nc, P, xs, ys, acc):
    """ys = G xs over the PENALTY points (index k * 2 + p); acc: per-body (fx, fy, torque) scratch."""
    acc[:] = 0.0
    for k in range(nc):
        for p in range(C.count[k]):
            if P.role[k, p] == PENALTY:
                f = math.sqrt(P.mass_n[k, p]) * xs[k * 2 + p]
                for x in (C.a[k], C.b[k]):
                    sg, rn = _row(C, P, k, p, x)
                    acc[x, 0] += sg * f * C.normal[k, 0]
                    acc[x, 1] += sg * f * C.normal[k, 1]
                    acc[x, 2] += sg * f * rn
    for k in range(nc):
        for p in range(2):  # every slot written: the unused ones (p >= count) stay 0
            y = 0.0
            if p < C.count[k] and P.role[k, p] == PENALTY:
                for x in (C.a[k], C.b[k]):
                    sg, rn = _row(C, P, k, p, x)
                    y += sg * (B.inv_m[x] * (acc[x, 0] * C.normal[k, 0] + acc[x, 1] * C.normal[k, 1])
                               + B.inv_i[x] * acc[x, 2] * rn)
                y *= math.sqrt(P.mass_n[k, p])
            ys[k * 2 + p] = y


@kernel(entry=True, runtime=True)
def gram_lambda(B, C, nc, P, iterations):
    """Largest eigenvalue of the PENALTY points' Gram matrix G (power iteration, Rayleigh quotient)."""
    m = 2 * nc
    xs = np.empty(m)
    for i in range(m):  # a fixed, deterministic start with no symmetry a scene could share
        k = i // 2
        used = i % 2 < C.count[k] and P.role[k, i % 2] == PENALTY
        xs[i] = 1.0 + 0.5 * math.sin(12.9898 * i + 1.0) if used else 0.0
    ys = np.empty(m)
    acc = np.empty((B.inv_m.shape[0], 3))
    lam = 0.0
    for _ in range(iterations):
        _gram_product(B, C, nc, P, xs, ys, acc)
        xx = 0.0
        xy = 0.0
        for i in range(m):
            xx += xs[i] * xs[i]
            xy += xs[i] * ys[i]
        if xx <= 0.0 or xy <= 0.0:
            return lam
        lam = xy / xx
        norm = 0.0
        for i in range(m):
            norm += ys[i] * ys[i]
        norm = math.sqrt(norm)
        for i in range(m):
            xs[i] = ys[i] / norm
    return lam


@kernel
def scale_penalty_points(B, C, nc, P, limit):
    """P.scale of every PENALTY point: 1, or limit / lambda_max where the points' fastest mode
    lambda_max (gram_lambda) exceeds the limit."""
    s = 1.0
    if nc > 0 and limit < math.inf:
        lam = gram_lambda(B, C, nc, P, np.int64(ITERATIONS))  # not a literal: one kernel
        if lam > limit:  # beyond the measured limit: back to the linear bound, with its margin
            s = 0.5 * limit / lam
    for k in range(nc):
        for p in range(C.count[k]):
            P.scale[k, p] = s
