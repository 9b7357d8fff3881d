"""Where a spring's anchors are, and its axis row there: what every spring formulation shares."""
from __future__ import annotations

import math

from ..._jit import kernel
from ..point import cross
from . import geometric as geo
from .implicit import JAW, JAX, JAY, JBW, JBX, JBY, row_speed

SKIP, EXPLICIT, IMPLICIT = 0, 1, 2  # a spring's kind in a sub-step (substep.py)


@kernel
def anchor(X, Q, R, i, lx, ly):
    """World position of body-frame point (lx, ly) of body i, and its arm r = R(q) l.

    ``X``, ``Q`` are positions and angles: the body table's, or an integrator's
    intermediate state (Runge-Kutta evaluates forces there).  ``R``: the bodies' (cos q, sin q)
    when the caller worked them out once per body (``rotate``), or None (from ``Q`` here): a body
    holding several springs' ends needs its angle's sine and cosine once, not once per end."""
    if R is None:
        c = math.cos(Q[i])
        s = math.sin(Q[i])
    else:
        c = R[i, 0]
        s = R[i, 1]
    rx = c * lx - s * ly
    ry = s * lx + c * ly
    return X[i, 0] + rx, X[i, 1] + ry, rx, ry


@kernel
def rotate(R, i, q):
    """Row i of a rotation cache (``anchor``'s R): (cos q, sin q)."""
    R[i, 0] = math.cos(q)
    R[i, 1] = math.sin(q)


@kernel
def ends(X, Q, R, S, k):
    """Spring k's anchors in the world and their arms: (pax, pay, rax, ray, pbx, pby, rbx, rby);
    an end on the world (b < 0) is its fixed point with no arm (``R`` as ``anchor``'s)."""
    a = S.a[k]
    b = S.b[k]
    pax, pay, rax, ray = anchor(X, Q, R, a, S.la[k, 0], S.la[k, 1])
    if b >= 0:
        pbx, pby, rbx, rby = anchor(X, Q, R, b, S.lb[k, 0], S.lb[k, 1])
    else:
        pbx, pby, rbx, rby = S.lb[k, 0], S.lb[k, 1], 0.0, 0.0
    return pax, pay, rax, ray, pbx, pby, rbx, rby


@kernel
def movable(B, i):
    """Body slot i exists (i >= 0) and responds to impulses."""
    return i >= 0 and (B.inv_m[i] > 0.0 or B.inv_i[i] > 0.0)


@kernel
def spring_rows(B, X, Q, R, S, ns, G, rows, bod, kinv, kind):
    """Axis, arms, length, stretch and tension (G), the axis row (rows[k], K in kinv) of every
    spring with the bodies at positions ``X`` and angles ``Q`` (their rotations ``R``, as
    ``anchor``'s; the velocities are the table's); SKIP where the axis is undefined or the spring
    exerts nothing."""
    for k in range(ns):
        kind[k] = SKIP
        a = S.a[k]
        b = S.b[k]
        pax, pay, rax, ray, pbx, pby, rbx, rby = ends(X, Q, R, S, k)
        dx = pbx - pax
        dy = pby - pay
        length = math.hypot(dx, dy)
        if length < 1e-12 or (S.k[k] == 0.0 and S.c[k] == 0.0):
            continue  # no axis (the force direction is undefined at zero length) or no force
        ux = dx / length
        uy = dy / length
        bod[k, 0] = a
        bod[k, 1] = b
        rows[k, JAX] = -ux
        rows[k, JAY] = -uy
        rows[k, JAW] = -cross(rax, ray, ux, uy)
        rows[k, JBX] = ux
        rows[k, JBY] = uy
        rows[k, JBW] = cross(rbx, rby, ux, uy)
        # summed in this order so that springs without geometric rows keep their trajectories bit for bit
        imb = B.inv_m[b] if b >= 0 else 0.0
        iib = B.inv_i[b] if b >= 0 else 0.0
        kinv[k] = B.inv_m[a] + imb + B.inv_i[a] * rows[k, JAW] * rows[k, JAW] + iib * rows[k, JBW] * rows[k, JBW]
        if kinv[k] == 0.0:
            continue
        stretch = length - S.rest[k]
        G[k, geo.UX] = ux
        G[k, geo.UY] = uy
        G[k, geo.RAX] = rax
        G[k, geo.RAY] = ray
        G[k, geo.RBX] = rbx
        G[k, geo.RBY] = rby
        G[k, geo.LEN] = length
        G[k, geo.STRETCH] = stretch
        G[k, geo.TENSION] = S.k[k] * stretch + S.c[k] * row_speed(B.v, B.w, rows, bod, k)
        kind[k] = IMPLICIT
