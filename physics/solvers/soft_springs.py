"""Springs inside the sub-stepped solvers.

A spring with stiffness k and damping c between anchors is applied as an
impulse along its axis each sub-step.  While k h^2 K and c h K are small
(K the effective inverse mass along the axis) the explicit symplectic
impulse -h (k C + c dC/dt) is accurate and conserves energy well.  Beyond
that it would blow up, so the spring switches to the implicit (soft
constraint) form of Catto's "Soft Constraints" (GDC 2011):
  gamma = 1 / (h (c + h k)),  bias = C h k gamma,
  impulse = -(dC/dt + bias) / (K + gamma),
which is backward Euler on the spring and stable for any stiffness.
"""
from __future__ import annotations

import math

from .._jit import kernel
from .contact_prep import cross

# explicit while the spring's k h^2 K stays below this (symplectic Euler is stable to 4)
_EXPLICIT_LIMIT = 0.25


@kernel
def _anchor(B, i, lx, ly):
    """World anchor and its offset from the centre of mass for a body-frame anchor."""
    c = math.cos(B.q[i])
    s = math.sin(B.q[i])
    rx = c * lx - s * ly
    ry = s * lx + c * ly
    return B.x[i, 0] + rx, B.x[i, 1] + ry, rx, ry


@kernel
def solve_springs(B, S, ns, h):
    for k in range(ns):
        a = S.a[k]
        b = S.b[k]
        pax, pay, rax, ray = _anchor(B, a, S.la[k, 0], S.la[k, 1])
        if b >= 0:
            pbx, pby, rbx, rby = _anchor(B, b, S.lb[k, 0], S.lb[k, 1])
            imb = B.inv_m[b]
            iib = B.inv_i[b]
            vbx = B.v[b, 0] - B.w[b] * rby
            vby = B.v[b, 1] + B.w[b] * rbx
        else:
            pbx = S.lb[k, 0]
            pby = S.lb[k, 1]
            rbx = 0.0
            rby = 0.0
            imb = 0.0
            iib = 0.0
            vbx = 0.0
            vby = 0.0
        dx = pbx - pax
        dy = pby - pay
        length = math.hypot(dx, dy)
        if length < 1e-12:
            continue  # no axis: the force direction is undefined at zero length
        ux = dx / length
        uy = dy / length
        ra_u = cross(rax, ray, ux, uy)
        rb_u = cross(rbx, rby, ux, uy)
        kinv = B.inv_m[a] + imb + B.inv_i[a] * ra_u * ra_u + iib * rb_u * rb_u
        if kinv == 0.0:
            continue
        vax = B.v[a, 0] - B.w[a] * ray
        vay = B.v[a, 1] + B.w[a] * rax
        cdot = (vbx - vax) * ux + (vby - vay) * uy
        stretch = length - S.rest[k]
        kk = S.k[k]
        cc = S.c[k]
        if kk * h * h * kinv < _EXPLICIT_LIMIT and cc * h * kinv < _EXPLICIT_LIMIT:
            # Hooke + damper (seed eqs. 18-20), explicit: impulse on b along +u
            j = -h * (kk * stretch + cc * cdot)
        else:
            gamma = 1.0 / (h * (cc + h * kk))
            bias = stretch * h * kk * gamma
            j = -(cdot + bias) / (kinv + gamma)
        px = j * ux
        py = j * uy
        B.v[a, 0] -= B.inv_m[a] * px
        B.v[a, 1] -= B.inv_m[a] * py
        B.w[a] -= B.inv_i[a] * cross(rax, ray, px, py)
        if b >= 0:
            B.v[b, 0] += imb * px
            B.v[b, 1] += imb * py
            B.w[b] += iib * cross(rbx, rby, px, py)
