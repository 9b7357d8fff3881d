"""Force generators (seed 7.1): gravity, user forces, damped springs (seed 7.2).

``eval_forces`` fills F (n, 2) and T (n,) for the state (X, Q, V, W) handed
to it, not necessarily the bodies' stored state: Runge-Kutta evaluates the
generators at its intermediate states (the seed asks for springs to be
integrated that way).  Only awake dynamic bodies receive forces.  Springs
are skipped entirely when there are none, and the penalty contact springs
(seed eq. 17) only when the penalty or hybrid mode switches them on.
"""
from __future__ import annotations

import math

from ._jit import kernel
from .solvers.penalty_force import penalty_forces
from .store import DYNAMIC


@kernel
def anchor(X, Q, i, lx, ly):
    """World position of body-frame point (lx, ly) of body i, and its arm r = R(q) l."""
    c = math.cos(Q[i])
    s = math.sin(Q[i])
    rx = c * lx - s * ly
    ry = s * lx + c * ly
    return X[i, 0] + rx, X[i, 1] + ry, rx, ry


@kernel
def gravity_and_user(B, n, gx, gy, F, T):
    """F = m g + f_user, T = tau_user for awake dynamic bodies; zero for everything else."""
    for i in range(n):
        if B.kind[i] != DYNAMIC or B.awake[i] == 0:
            F[i, 0] = 0.0
            F[i, 1] = 0.0
            T[i] = 0.0
            continue
        F[i, 0] = B.m[i] * gx + B.f[i, 0]
        F[i, 1] = B.m[i] * gy + B.f[i, 1]
        T[i] = B.tau[i]


@kernel
def spring_forces(S, ns, X, Q, V, W, F, T):
    """Hooke plus axial damping, equal and opposite at the anchors (seed eqs. 18-20).

    d = x_A - x_B (eq. 20), f_A = -(k (|d| - l0) + c (v_A - v_B).d^) d^ (eq. 19 with a
    damper on the relative velocity along the axis), f_B = -f_A.  The anchors move
    with the bodies, so each force also makes a torque r x f.
    """
    for s in range(ns):
        a = S.a[s]
        b = S.b[s]
        pax, pay, rax, ray = anchor(X, Q, a, S.la[s, 0], S.la[s, 1])
        vax = V[a, 0] - W[a] * ray
        vay = V[a, 1] + W[a] * rax
        if b >= 0:
            pbx, pby, rbx, rby = anchor(X, Q, b, S.lb[s, 0], S.lb[s, 1])
            vbx = V[b, 0] - W[b] * rby
            vby = V[b, 1] + W[b] * rbx
        else:
            pbx, pby, rbx, rby = S.lb[s, 0], S.lb[s, 1], 0.0, 0.0
            vbx = 0.0
            vby = 0.0
        dx = pax - pbx
        dy = pay - pby
        length = math.hypot(dx, dy)
        if length < 1e-12:  # direction undefined: no axis, no force
            continue
        ux = dx / length
        uy = dy / length
        mag = -S.k[s] * (length - S.rest[s]) - S.c[s] * ((vax - vbx) * ux + (vay - vby) * uy)
        fx = mag * ux
        fy = mag * uy
        F[a, 0] += fx
        F[a, 1] += fy
        T[a] += rax * fy - ray * fx
        if b >= 0:
            F[b, 0] -= fx
            F[b, 1] -= fy
            T[b] -= rbx * fy - rby * fx


@kernel
def eval_forces(B, n, S, ns, C, nc, gx, gy, X, Q, V, W, F, T, R, pen):
    """All force generators at the state (X, Q, V, W) into F, T."""
    gravity_and_user(B, n, gx, gy, F, T)
    if ns > 0:
        spring_forces(S, ns, X, Q, V, W, F, T)
    if pen[0] > 0.0 and nc > 0:
        penalty_forces(B, C, nc, X, Q, V, W, R.X0, R.Q0, F, T, pen)
    for i in range(n):  # forces on bodies that may not move are dropped
        if B.kind[i] != DYNAMIC or B.awake[i] == 0:
            F[i, 0] = 0.0
            F[i, 1] = 0.0
            T[i] = 0.0
