"""Springs as force generators (seed 7.2, eqs. 18-20): the form the seed's integrators use.

``spring_forces`` adds each spring's force at a given state (X, Q, V, W), so an
explicit integrator (Euler, symplectic Euler, RK4: physics/solvers/classic/)
can evaluate it at its intermediate states.  ``spring_rate`` sizes the
integrator's sub-steps for the stiffest spring.
"""
from __future__ import annotations

import math

from ..._jit import kernel
from .geometry import ends


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
        pax, pay, rax, ray, pbx, pby, rbx, rby = ends(X, Q, None, S, s)
        vax = V[a, 0] - W[a] * ray
        vay = V[a, 1] + W[a] * rax
        vbx = 0.0
        vby = 0.0
        if b >= 0:
            vbx = V[b, 0] - W[b] * rby
            vby = V[b, 1] + W[b] * rbx
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
def _geometric_rate(B, S, s):
    """omega^2 bound of spring s's geometric stiffness at the bodies' state (geometric.py):
    |T| / L across the axis plus |f . r| / I at each arm (both signs: a negative stiffness
    diverges as fast as a positive one oscillates)."""
    a = S.a[s]
    b = S.b[s]
    pax, pay, rax, ray, pbx, pby, rbx, rby = ends(B.x, B.q, None, S, s)
    inv_m = B.inv_m[a]
    if b >= 0:
        inv_m += B.inv_m[b]
    length = math.hypot(pbx - pax, pby - pay)
    if length < 1e-12:
        return 0.0
    t = abs(S.k[s] * (length - S.rest[s]))
    ra = math.hypot(rax, ray)
    rb = math.hypot(rbx, rby)
    rate = t / length * (inv_m + ra * ra * B.inv_i[a]) + t * ra * B.inv_i[a]
    if b >= 0:
        rate += t / length * rb * rb * B.inv_i[b] + t * rb * B.inv_i[b]
    return rate


@kernel(entry=True)
def spring_rate(B, S, ns):
    """Largest omega = sqrt(k / m_eff), damping rate c / m_eff and geometric omega over the springs.

    1/m_eff at an anchor is bounded by 1/m + |r|^2 / I per end (the spring axis
    may be perpendicular to the arm); the geometric omega is that of the turning
    axis and arms (_geometric_rate).
    """
    worst = 0.0
    for s in range(ns):
        a = S.a[s]
        inv = B.inv_m[a] + (S.la[s, 0] ** 2 + S.la[s, 1] ** 2) * B.inv_i[a]
        b = S.b[s]
        if b >= 0:
            inv += B.inv_m[b] + (S.lb[s, 0] ** 2 + S.lb[s, 1] ** 2) * B.inv_i[b]
        worst = max(worst, math.sqrt(S.k[s] * inv), S.c[s] * inv, math.sqrt(_geometric_rate(B, S, s)))
    return worst
