"""Soft contact constraints solved per sub-step (Catto, "Solver2D" 2024 / Box2D v3).

A contact is a stiff damped spring expressed as a velocity constraint: with
stiffness omega = 2 pi f and damping ratio zeta over sub-step h,
  bias_rate = omega / (2 zeta + h omega),
  mass_scale = h omega (2 zeta + h omega) / (1 + h omega (2 zeta + h omega)),
  impulse_scale = 1 / (1 + h omega (2 zeta + h omega)),
so overlap is removed smoothly at a rate capped by the push-out speed, and
the relax pass (no bias) then removes the velocity the bias added.  The
current separation of each point is rebuilt from the bodies' motion since
the step began, so one narrow phase per step serves every sub-step.
"""
from __future__ import annotations

import math

from .._jit import kernel
from .block_normal import block_normal
from .contact_prep import apply_impulse, rel_velocity


@kernel
def softness(hertz, zeta, h):
    """(bias_rate, mass_scale, impulse_scale) of a soft constraint; hertz 0 = rigid."""
    if hertz <= 0.0:
        return 0.0, 1.0, 0.0
    omega = 2.0 * math.pi * hertz
    a1 = 2.0 * zeta + h * omega
    a2 = h * omega * a1
    a3 = 1.0 / (1.0 + a2)
    return omega / a1, a2 * a3, a3


@kernel
def current_separation(C, k, p, DP, DC, DS, a, b):
    """Separation now: the step's initial one moved by each body's displacement.

    The anchor of a point on body i has moved by dp_i + (R(dq_i) - I) r_i.
    """
    rax = C.ra[k, p, 0]
    ray = C.ra[k, p, 1]
    rbx = C.rb[k, p, 0]
    rby = C.rb[k, p, 1]
    dax = DP[a, 0] + (DC[a] - 1.0) * rax - DS[a] * ray
    day = DP[a, 1] + DS[a] * rax + (DC[a] - 1.0) * ray
    dbx = DP[b, 0] + (DC[b] - 1.0) * rbx - DS[b] * rby
    dby = DP[b, 1] + DS[b] * rbx + (DC[b] - 1.0) * rby
    return -C.depth[k, p] + (dbx - dax) * C.normal[k, 0] + (dby - day) * C.normal[k, 1]


@kernel
def warm_start(B, C, nc):
    for k in range(nc):
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        for p in range(C.count[k]):
            jn = C.jn[k, p]
            jt = C.jt[k, p]
            px = jn * nx - jt * ny
            py = jn * ny + jt * nx
            apply_impulse(B, a, b, C.ra[k, p, 0], C.ra[k, p, 1], C.rb[k, p, 0], C.rb[k, p, 1], px, py)


@kernel
def _row_bias(C, k, p, DP, DC, DS, a, b, inv_h, use_bias, rate, mscale, iscale, push_speed):
    """(bias, mass scale, impulse scale) of one normal row in this pass."""
    sep = current_separation(C, k, p, DP, DC, DS, a, b)
    if sep > 0.0:
        return sep * inv_h, 1.0, 0.0  # speculative: may approach until touching, no further
    if use_bias:
        return max(rate * sep, -push_speed), mscale, iscale
    return 0.0, 1.0, 0.0


@kernel
def solve_contacts(B, C, nc, DP, DC, DS, inv_h, use_bias, soft_dyn, soft_static, push_speed, block):
    """One Gauss-Seidel pass: soft normal impulses (>= 0), then Coulomb-clamped friction.

    With ``block`` the two normal rows of a face contact are solved together
    (block_normal.py) when both are in the same regime (both soft or both rigid).
    """
    for k in range(nc):
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        rigid_pair = B.inv_m[a] == 0.0 or B.inv_m[b] == 0.0
        rate, mscale, iscale = soft_static if rigid_pair else soft_dyn
        done = False
        if block and C.count[k] == 2:
            b0, ms0, _ = _row_bias(C, k, 0, DP, DC, DS, a, b, inv_h, use_bias, rate, mscale, iscale, push_speed)
            b1, ms1, _ = _row_bias(C, k, 1, DP, DC, DS, a, b, inv_h, use_bias, rate, mscale, iscale, push_speed)
            if ms0 == ms1:
                done = block_normal(B, C, k, a, b, nx, ny, b0, b1, ms0)
        if not done:
            for p in range(C.count[k]):
                rax = C.ra[k, p, 0]
                ray = C.ra[k, p, 1]
                rbx = C.rb[k, p, 0]
                rby = C.rb[k, p, 1]
                bias, ms, isc = _row_bias(C, k, p, DP, DC, DS, a, b, inv_h, use_bias, rate, mscale, iscale,
                                          push_speed)
                dvx, dvy = rel_velocity(B, a, b, rax, ray, rbx, rby)
                vn = dvx * nx + dvy * ny
                old = C.jn[k, p]
                j = -C.mass_n[k, p] * ms * (vn + bias) - isc * old
                new = max(old + j, 0.0)
                C.jn[k, p] = new
                j = new - old
                apply_impulse(B, a, b, rax, ray, rbx, rby, j * nx, j * ny)
        for p in range(C.count[k]):
            rax = C.ra[k, p, 0]
            ray = C.ra[k, p, 1]
            rbx = C.rb[k, p, 0]
            rby = C.rb[k, p, 1]
            dvx, dvy = rel_velocity(B, a, b, rax, ray, rbx, rby)
            vt = -dvx * ny + dvy * nx
            limit = C.mu[k, p] * C.jn[k, p]
            old = C.jt[k, p]
            new = min(max(old - C.mass_t[k, p] * vt, -limit), limit)
            C.jt[k, p] = new
            j = new - old
            apply_impulse(B, a, b, rax, ray, rbx, rby, -j * ny, j * nx)


@kernel
def track_max_impulse(C, nc, M, reset):
    """M[k, p] = the largest normal impulse point (k, p) carried so far this step.

    Restitution must know whether a point took part in the step's collision:
    by the last sub-step a stopped body's impulse is back to 0 (Box2D v3 keeps
    ``maxNormalImpulse`` for this).  ``M`` is C.bias, unused by soft_step."""
    for k in range(nc):
        for p in range(2):
            if reset:
                M[k, p] = 0.0
            elif C.jn[k, p] > M[k, p]:
                M[k, p] = C.jn[k, p]


@kernel
def apply_restitution(B, C, nc, threshold, M):
    """Newton's law v_n' = -e v_n (seed eq. 13) for points that hit faster than ``threshold``.

    Only points that pushed this step (M[k, p] > 0: the accumulated or the
    largest normal impulse) bounce; a speculative point never reached does not."""
    for k in range(nc):
        e = C.e[k]
        if e == 0.0:
            continue
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        for p in range(C.count[k]):
            if C.vn0[k, p] > -threshold or M[k, p] == 0.0:
                continue
            rax = C.ra[k, p, 0]
            ray = C.ra[k, p, 1]
            rbx = C.rb[k, p, 0]
            rby = C.rb[k, p, 1]
            dvx, dvy = rel_velocity(B, a, b, rax, ray, rbx, rby)
            vn = dvx * nx + dvy * ny
            old = C.jn[k, p]
            new = max(old - C.mass_n[k, p] * (vn + e * C.vn0[k, p]), 0.0)
            C.jn[k, p] = new
            j = new - old
            apply_impulse(B, a, b, rax, ray, rbx, rby, j * nx, j * ny)
