"""Soft contact constraints (Catto, "Solver2D" 2024 / Box2D v3): the pieces shared by modes.

A contact is a stiff damped spring expressed as a velocity constraint: with
stiffness omega = 2 pi f and damping ratio zeta over sub-step h,
  bias_rate = omega / (2 zeta + h omega),
  mass_scale = h omega (2 zeta + h omega) / (1 + h omega (2 zeta + h omega)),
  impulse_scale = 1 / (1 + h omega (2 zeta + h omega)),
so overlap is removed smoothly at a rate capped by the push-out speed, and
the relax pass (no bias) then removes the velocity the bias added.  The
sub-step passes themselves live in soft_rows.py (soft_step); this module keeps
the softness coefficients, the warm start over contact rows and the
restitution pass that sequential_impulse shares.
"""
from __future__ import annotations

import math

from .._jit import kernel
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
