"""Contact geometry shared by the seed modes (impulse, penalty, hybrid).

The narrow phase runs once, at the start of the step; these modes then move
the bodies (force integration) before resolving contacts, as the seed does
(detect after moving, then respond).  A contact point's depth at any later
state is the step-start depth minus the relative displacement of the two
material points along the normal: the anchors ``ra``/``rb`` (filled by
``contact_prep.prepare_contacts`` at the step start) are carried along with
each body's translation and rotation since the step began.  This is exact
for translation and first order in the rotation of the normal.

Per-point role flags live in the ``bias`` scratch column: 0 inactive,
1 resolved by impulses, 2 held by a penalty spring.
"""
from __future__ import annotations

import math

from .._jit import kernel

INACTIVE, IMPULSE, PENALTY = 0.0, 1.0, 2.0


@kernel
def moved_arm(X, Q, X0, Q0, i, rx, ry):
    """Arm of a material point (step-start arm r) now, and that point's displacement."""
    dq = Q[i] - Q0[i]
    c = math.cos(dq)
    s = math.sin(dq)
    nx = c * rx - s * ry
    ny = s * rx + c * ry
    return nx, ny, X[i, 0] - X0[i, 0] + nx - rx, X[i, 1] - X0[i, 1] + ny - ry


@kernel
def depth_at(C, k, p, X, Q, X0, Q0):
    """Depth of point p of row k at the state (X, Q); also the current arms."""
    a = C.a[k]
    b = C.b[k]
    rax, ray, dax, day = moved_arm(X, Q, X0, Q0, a, C.ra[k, p, 0], C.ra[k, p, 1])
    rbx, rby, dbx, dby = moved_arm(X, Q, X0, Q0, b, C.rb[k, p, 0], C.rb[k, p, 1])
    d = C.depth[k, p] - ((dbx - dax) * C.normal[k, 0] + (dby - day) * C.normal[k, 1])
    return d, rax, ray, rbx, rby


@kernel
def rel_vel(V, W, a, b, rax, ray, rbx, rby):
    """Velocity of b's material point minus a's (seed eqs. 12 and 14, sign: b - a)."""
    dvx = (V[b, 0] - W[b] * rby) - (V[a, 0] - W[a] * ray)
    dvy = (V[b, 1] + W[b] * rbx) - (V[a, 1] + W[a] * rax)
    return dvx, dvy


@kernel
def push(X, Q, i, inv_m, inv_i, rx, ry, px, py):
    """Apply a force/impulse-like vector P at arm r to the pair (F, T) or (v, w) arrays."""
    X[i, 0] += inv_m * px
    X[i, 1] += inv_m * py
    Q[i] += inv_i * (rx * py - ry * px)
