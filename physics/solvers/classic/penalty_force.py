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
spring (stretch s in the contact table's ``stick``, carried between steps by
the narrow phase) plus damping, capped at mu F_n with mu_s while the
point sticks (|v_t| below the stick speed) and mu_d while it slides.  Unlike
a purely viscous regularisation, the stick spring holds a box on a slope
without creep.

Deep overlap (bodies created inside each other) would turn the spring's
stored energy m omega^2 d^2 / 2 into a separation speed omega d: 157 m/s for
1 m at 25 Hz.  The depth term is therefore capped like soft_step's push-out
(``push_out_speed`` v_p): written as a velocity servo,
    F_n = m_eff 2 zeta omega (v_target - v_n),  v_target = omega d / (2 zeta),
the target is capped at v_p with zeta raised to at least 1/2 beyond the cap
while the pair separates, so the force vanishes once it separates at v_p
(an approaching pair keeps its own damping).  Overlap loaded by an impact
is not push-out: each point remembers the fastest approach it has seen (in
the contact table's ``approach``, carried by the narrow phase's feature
matching while the rows live) and its cap is the larger of v_p and twice that speed, so an elastic
bounce returns at the speed it came in.  Contacts shallower than
2 zeta v_p / omega (2.5 cm at 25 Hz, zeta 1, 2 m/s; resting contact sinks
0.5 mm) are untouched.

Several points on one body stiffen it beyond what the sub-step count allows for one
point; penalty_load.py scales those points' stiffness and damping (``P.scale``).

``pen``: [on, omega, zeta, stick_speed, push_out_speed, load limit (penalty_load.stable_load)].
"""
from __future__ import annotations

import math

from ..._jit import kernel
from .contact_geometry import PENALTY, depth_at, push, rel_vel


@kernel
def damping_ratio(e, zeta):
    if e <= 0.0:
        return zeta
    le = math.log(e)
    return min(zeta, -le / math.sqrt(math.pi * math.pi + le * le))


@kernel
def normal_force(mn, omega, zeta, d, vn, vmax):
    """m (omega^2 d - 2 zeta omega v_n), its depth term capped so it separates at most at vmax."""
    zc = max(zeta, 0.5)
    if omega * d <= 2.0 * zc * vmax:
        return mn * omega * (omega * d - 2.0 * zeta * vn)
    # beyond the cap: approaching, the contact's own damping (a fast impact is not braked);
    # separating, at least half-critical, so the push stops at vn = vmax
    return mn * omega * 2.0 * (zc * vmax - (zeta if vn < 0.0 else zc) * vn)


@kernel
def push_cap(C, k, p, pen):
    """The point's push-out cap: push_out_speed, or twice the approach speed the point remembers
    (an elastic bounce reaches omega d = v_in only for one point in continuous time; two points
    of a face and the sub-step discretisation take it somewhat past that)."""
    return max(pen[4], -2.0 * C.approach[k, p])


@kernel
def penalty_point(B, C, P, k, p, X, Q, V, W, X0, Q0, pen):
    """(depth, F_n, trial tangential force, arms) of one penalty point at a state."""
    omega = pen[1]
    d, rax, ray, rbx, rby = depth_at(C, P, k, p, X, Q, X0, Q0)
    if d <= 0.0:
        return d, 0.0, 0.0, 0.0, rax, ray, rbx, rby
    nx = C.normal[k, 0]
    ny = C.normal[k, 1]
    dvx, dvy = rel_vel(V, W, C.a[k], C.b[k], rax, ray, rbx, rby)
    vn = dvx * nx + dvy * ny
    vt = -dvx * ny + dvy * nx
    mn = P.mass_n[k, p] * P.scale[k, p]  # scale < 1 only where several points load one body
    fn = max(0.0, normal_force(mn, omega, damping_ratio(C.e[k], pen[2]), d, vn, push_cap(C, k, p, pen)))
    mt = P.mass_t[k, p] * P.scale[k, p]
    ft = -mt * omega * (omega * C.stick[k, p] + 2.0 * vt)
    return d, fn, ft, vt, rax, ray, rbx, rby


@kernel
def friction_cap(C, k, vt, fn, stick):
    return (C.mu_s[k] if abs(vt) <= stick else C.mu_d[k]) * fn


@kernel
def penalty_forces(B, C, nc, P, X, Q, V, W, X0, Q0, F, T, pen):
    """Add the penalty forces of every PENALTY point at the state (X, Q, V, W)."""
    for k in range(nc):
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        for p in range(C.count[k]):
            if P.role[k, p] != PENALTY:
                continue
            d, fn, ft, vt, rax, ray, rbx, rby = penalty_point(B, C, P, k, p, X, Q, V, W, X0, Q0, pen)
            if fn <= 0.0:
                continue
            lim = friction_cap(C, k, vt, fn, pen[3])
            ft = min(lim, max(-lim, ft))
            px = fn * nx - ft * ny
            py = fn * ny + ft * nx
            push(F, T, b, 1.0, 1.0, rbx, rby, px, py)
            push(F, T, a, 1.0, 1.0, rax, ray, -px, -py)


@kernel
def update_stick(B, C, nc, P, R, h, pen):
    """After a sub-step: stretch the stick springs by v_t h, slip where they exceed mu F_n;
    remember the fastest approach (as the most negative normal speed); add F h to the points'
    ``jn``/``jt`` (zeroed at the step's start by ``advance``)."""
    for k in range(nc):
        for p in range(C.count[k]):
            if P.role[k, p] != PENALTY:
                continue
            d, fn, ft, vt, rax, ray, rbx, rby = penalty_point(B, C, P, k, p, B.x, B.q, B.v, B.w,
                                                              R.X0, R.Q0, pen)
            dvx, dvy = rel_vel(B.v, B.w, C.a[k], C.b[k], rax, ray, rbx, rby)
            vn = dvx * C.normal[k, 0] + dvy * C.normal[k, 1]
            C.approach[k, p] = min(C.approach[k, p], min(0.0, vn))
            # the contact's impulse of the step (views.contacts): F h summed over the sub-steps, F
            # the force the next sub-step starts from (symplectic Euler applies exactly that one);
            # the solve never reads it back
            lim = friction_cap(C, k, vt, fn, pen[3])
            C.jn[k, p] += fn * h
            if d <= 0.0:
                C.stick[k, p] = 0.0
                continue
            s = C.stick[k, p] + h * vt
            mt = P.mass_t[k, p] * P.scale[k, p]
            kt = mt * pen[1] * pen[1]
            smax = lim / kt if kt > 0.0 else 0.0
            C.stick[k, p] = min(smax, max(-smax, s))
            ft = -mt * pen[1] * (pen[1] * C.stick[k, p] + 2.0 * vt)  # with the new stretch
            C.jt[k, p] += min(lim, max(-lim, ft)) * h
