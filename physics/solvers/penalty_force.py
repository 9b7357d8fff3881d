"""Penalty contact as a force generator (seed 6.2, eq. 17).

The seed writes the penalty response as an impulse J = C P with P the
penetration vector and C a frame-rate constant.  We integrate the force
behind it instead, a damped spring along the normal,
    F_n = m_eff (omega^2 d - 2 zeta omega v_n),  F_n >= 0 (contacts only push),
with m_eff the point's effective normal mass: stiffness is set as a frequency,
so a heavy box sinks no deeper than a light one.  Per step and sub-step h the
impulse is J = F_n h: eq. 17's C is h m_eff omega^2.

The damping ratio follows the contact's restitution (a linear spring-damper
bounces back with e = exp(-zeta pi / sqrt(1 - zeta^2))), capped by the mode's
setting; e = 0 uses the setting.

Friction is a regularised Coulomb force (seed eq. 23): a tangential stick
spring (stretch s stored in the row's ``jt``, carried between steps by the
narrow phase's warm start) plus damping, capped at mu F_n with mu_s while the
point sticks (|v_t| below the stick speed) and mu_d while it slides.  Unlike
a purely viscous regularisation, the stick spring holds a box on a slope
without creep.

``pen``: [on, omega, zeta, stick_speed].
"""
from __future__ import annotations

import math

from .._jit import kernel
from .seed_contact import PENALTY, depth_at, push, rel_vel


@kernel
def damping_ratio(e, zeta):
    if e <= 0.0:
        return zeta
    le = math.log(e)
    return min(zeta, -le / math.sqrt(math.pi * math.pi + le * le))


@kernel
def penalty_point(B, C, k, p, X, Q, V, W, X0, Q0, pen):
    """(depth, F_n, trial tangential force, arms) of one penalty point at a state."""
    omega = pen[1]
    d, rax, ray, rbx, rby = depth_at(C, k, p, X, Q, X0, Q0)
    if d <= 0.0:
        return d, 0.0, 0.0, 0.0, rax, ray, rbx, rby
    nx = C.normal[k, 0]
    ny = C.normal[k, 1]
    dvx, dvy = rel_vel(V, W, C.a[k], C.b[k], rax, ray, rbx, rby)
    vn = dvx * nx + dvy * ny
    vt = -dvx * ny + dvy * nx
    mn = C.mass_n[k, p]
    zeta = damping_ratio(C.e[k], pen[2])
    fn = max(0.0, mn * omega * (omega * d - 2.0 * zeta * vn))
    mt = C.mass_t[k, p]
    ft = -mt * omega * (omega * C.jt[k, p] + 2.0 * vt)
    return d, fn, ft, vt, rax, ray, rbx, rby


@kernel
def friction_cap(C, k, vt, fn, stick):
    return (C.mu_s[k] if abs(vt) <= stick else C.mu_d[k]) * fn


@kernel
def penalty_forces(B, C, nc, X, Q, V, W, X0, Q0, F, T, pen):
    """Add the penalty forces of every PENALTY point at the state (X, Q, V, W)."""
    for k in range(nc):
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        for p in range(C.count[k]):
            if C.bias[k, p] != PENALTY:
                continue
            d, fn, ft, vt, rax, ray, rbx, rby = penalty_point(B, C, k, p, X, Q, V, W, X0, Q0, pen)
            if fn <= 0.0:
                continue
            lim = friction_cap(C, k, vt, fn, pen[3])
            ft = min(lim, max(-lim, ft))
            px = fn * nx - ft * ny
            py = fn * ny + ft * nx
            push(F, T, b, 1.0, 1.0, rbx, rby, px, py)
            push(F, T, a, 1.0, 1.0, rax, ray, -px, -py)


@kernel
def update_stick(B, C, nc, R, h, pen):
    """After a sub-step: stretch the stick springs by v_t h, slip where they exceed mu F_n."""
    for k in range(nc):
        for p in range(C.count[k]):
            if C.bias[k, p] != PENALTY:
                continue
            d, fn, ft, vt, rax, ray, rbx, rby = penalty_point(B, C, k, p, B.x, B.q, B.v, B.w,
                                                              R.X0, R.Q0, pen)
            if d <= 0.0:
                C.jt[k, p] = 0.0
                continue
            s = C.jt[k, p] + h * vt
            kt = C.mass_t[k, p] * pen[1] * pen[1]
            smax = friction_cap(C, k, vt, fn, pen[3]) / kt if kt > 0.0 else 0.0
            C.jt[k, p] = min(smax, max(-smax, s))
