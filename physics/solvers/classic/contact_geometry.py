"""Contact geometry shared by the seed modes (impulse, penalty, hybrid).

The narrow phase runs once, at the start of the step; these modes then move
the bodies (force integration) before resolving contacts, as the seed does
(detect after moving, then respond).  A contact point's depth at any later
state is the step-start depth minus the relative displacement of the two
material points along the normal: the arms ``ra``/``rb`` of the mode's point
rows ``P`` (constraints/point.py, filled at the step start) are carried along with
each body's translation and rotation since the step began.  This is exact
for translation and first order in the rotation of the normal.

Each point's role this step is ``P.role``: INACTIVE, IMPULSE (resolved by
impulses) or PENALTY (held by a penalty spring).  The point rows of these modes
are ``classic_points``: POINT_FIELDS plus ``role``, ``target`` (the
restitution target speed of an impulse point) and ``scale`` (the share of its
penalty stiffness a point keeps when several load one body: penalty_load.py).
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from ...constraints.point import point_rows, point_type, rel_velocity

INACTIVE, IMPULSE, PENALTY = 0, 1, 2
ClassicPoints = point_type("ClassicPoints", __name__, extra=(("role", np.int8), ("target", np.float64),
                                                         ("scale", np.float64)))


def classic_points(cap: int):
    """Point rows for ``cap`` manifolds (see the module doc)."""
    return point_rows(ClassicPoints, cap)


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
def depth_at(C, P, k, p, X, Q, X0, Q0):
    """Depth of point p of row k at the state (X, Q); also the current arms."""
    a = C.a[k]
    b = C.b[k]
    rax, ray, dax, day = moved_arm(X, Q, X0, Q0, a, P.ra[k, p, 0], P.ra[k, p, 1])
    rbx, rby, dbx, dby = moved_arm(X, Q, X0, Q0, b, P.rb[k, p, 0], P.rb[k, p, 1])
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


@kernel
def flag_all(C, nc, P, role):
    """Give every point of the first ``nc`` manifolds the same role."""
    for k in range(nc):
        for p in range(C.count[k]):
            P.role[k, p] = role


@kernel
def classify(B, C, nc, P, thr):
    """IMPULSE for points approaching faster than thr, PENALTY for the rest (hybrid)."""
    for k in range(nc):
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        for p in range(C.count[k]):
            dvx, dvy = rel_velocity(B, C.a[k], C.b[k], P.ra[k, p, 0], P.ra[k, p, 1], P.rb[k, p, 0],
                                    P.rb[k, p, 1])
            P.role[k, p] = IMPULSE if dvx * nx + dvy * ny < -thr else PENALTY
