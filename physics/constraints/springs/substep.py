"""Springs inside the sub-stepped solvers (soft_step, sequential_impulse): impulses on velocities.

A spring with stiffness k and damping c between anchors is applied as an
impulse along its axis each sub-step.  While the spring is soft for the
bodies it joins, the explicit symplectic impulse -h (k C + c dC/dt) is
accurate and conserves energy well.  Beyond that it would blow up, so the
spring switches to the implicit (soft constraint) form of Catto's "Soft
Constraints" (GDC 2011):
  gamma = 1 / (h (c + h k)),  bias = C h k gamma,
which is backward Euler on the spring.  All implicit springs are solved
together as one linear system (constraints/springs/implicit.py): solved one
by one in a single pass, a chain of light links carrying a heavy load only
passes on part of the load each sub-step and swings far beyond its stretch.

Explicit or implicit is decided per spring from the stiffness of every spring
at its two bodies, not the spring alone: symplectic Euler is stable while
h^2 lambda_max(W K) < 4, and lambda_max is bounded by the row sums
(Gershgorin) sum_s k_s K_s over the springs sharing a body, so a light body
held by many springs goes implicit even if each spring alone is soft.
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from ..point import cross
from .geometry import anchor, movable
from .implicit import DIAG, RA, RB, RHS, ROW_FIELDS, UX, UY, apply_system, solve_system

# explicit while h^2 sum k K (and h sum c K) at the spring's bodies stays below this
# (symplectic Euler is stable to 4: a 16x margin keeps the explicit springs accurate)
_EXPLICIT_LIMIT = 0.25
SKIP, EXPLICIT, IMPLICIT = 0, 1, 2


@kernel
def _geometry(B, S, ns, rows, kinv, stretch, kind):
    """Axis, arms x axis, K = J W J^T and stretch of every spring; SKIP where undefined."""
    for k in range(ns):
        kind[k] = SKIP
        a = S.a[k]
        b = S.b[k]
        pax, pay, rax, ray = anchor(B.x, B.q, a, S.la[k, 0], S.la[k, 1])
        if b >= 0:
            pbx, pby, rbx, rby = anchor(B.x, B.q, b, S.lb[k, 0], S.lb[k, 1])
            imb = B.inv_m[b]
            iib = B.inv_i[b]
        else:
            pbx, pby, rbx, rby = S.lb[k, 0], S.lb[k, 1], 0.0, 0.0
            imb = 0.0
            iib = 0.0
        dx = pbx - pax
        dy = pby - pay
        length = math.hypot(dx, dy)
        if length < 1e-12 or (S.k[k] == 0.0 and S.c[k] == 0.0):
            continue  # no axis (the force direction is undefined at zero length) or no force
        ux = dx / length
        uy = dy / length
        ra_u = cross(rax, ray, ux, uy)
        rb_u = cross(rbx, rby, ux, uy)
        kinv[k] = B.inv_m[a] + imb + B.inv_i[a] * ra_u * ra_u + iib * rb_u * rb_u
        if kinv[k] == 0.0:
            continue
        rows[k, UX] = ux
        rows[k, UY] = uy
        rows[k, RA] = ra_u
        rows[k, RB] = rb_u
        stretch[k] = length - S.rest[k]
        kind[k] = IMPLICIT


@kernel
def _classify(B, S, ns, h, kinv, kind, LK, LC):
    """EXPLICIT where h^2 sum k K and h sum c K over the springs at both bodies stay small."""
    for k in range(ns):
        for i in (S.a[k], S.b[k]):
            if i >= 0:
                LK[i] = 0.0
                LC[i] = 0.0
    for k in range(ns):
        if kind[k] == SKIP:
            continue
        for i in (S.a[k], S.b[k]):
            if movable(B, i):
                LK[i] += S.k[k] * kinv[k]
                LC[i] += S.c[k] * kinv[k]
    for k in range(ns):
        if kind[k] == SKIP:
            continue
        a = S.a[k]
        b = S.b[k]
        # row sum of this spring: its own k K once, plus its neighbours' at either end
        lk = LK[a] + (LK[b] if movable(B, b) else 0.0)
        lc = LC[a] + (LC[b] if movable(B, b) else 0.0)
        if movable(B, a) and movable(B, b):
            lk -= S.k[k] * kinv[k]
            lc -= S.c[k] * kinv[k]
        if lk * h * h < _EXPLICIT_LIMIT and lc * h < _EXPLICIT_LIMIT:
            kind[k] = EXPLICIT


@kernel
def _cdot(B, S, k, rows):
    """Rate of stretch dC/dt = (v_b + w_b x r_b - v_a - w_a x r_a) . u."""
    a = S.a[k]
    b = S.b[k]
    v = -(B.v[a, 0] * rows[k, UX] + B.v[a, 1] * rows[k, UY]) - B.w[a] * rows[k, RA]
    if b >= 0:
        v += B.v[b, 0] * rows[k, UX] + B.v[b, 1] * rows[k, UY] + B.w[b] * rows[k, RB]
    return v


@kernel
def _push(B, S, k, rows, j):
    """Impulse j on b along +u, -j on a."""
    a = S.a[k]
    b = S.b[k]
    B.v[a, 0] -= B.inv_m[a] * j * rows[k, UX]
    B.v[a, 1] -= B.inv_m[a] * j * rows[k, UY]
    B.w[a] -= B.inv_i[a] * j * rows[k, RA]
    if b >= 0:
        B.v[b, 0] += B.inv_m[b] * j * rows[k, UX]
        B.v[b, 1] += B.inv_m[b] * j * rows[k, UY]
        B.w[b] += B.inv_i[b] * j * rows[k, RB]


@kernel
def solve_springs(B, S, ns, h):
    cap = B.inv_m.shape[0]
    rows = np.zeros((ns, ROW_FIELDS))
    kinv = np.zeros(ns)
    stretch = np.zeros(ns)
    kind = np.zeros(ns, np.int8)
    LK = np.empty(cap)
    LC = np.empty(cap)
    _geometry(B, S, ns, rows, kinv, stretch, kind)
    _classify(B, S, ns, h, kinv, kind, LK, LC)
    # Hooke + damper (seed eqs. 18-20), explicit, in sequence (symplectic Euler)
    for k in range(ns):
        if kind[k] == EXPLICIT:
            _push(B, S, k, rows, -h * (S.k[k] * stretch[k] + S.c[k] * _cdot(B, S, k, rows)))
    # the implicit ones together, from the velocities the explicit ones left
    on = np.zeros(ns, np.bool_)
    gam = np.zeros(ns)
    n_on = 0
    for k in range(ns):
        if kind[k] != IMPLICIT:
            continue
        on[k] = True
        n_on += 1
        gam[k] = 1.0 / (h * (S.c[k] + h * S.k[k]))
        bias = stretch[k] * h * S.k[k] * gam[k]
        rows[k, DIAG] = kinv[k] + gam[k]
        rows[k, RHS] = -(_cdot(B, S, k, rows) + bias)
    if n_on == 0:
        return
    lam = np.zeros(ns)
    solve_system(B, S, ns, rows, on, gam, lam)
    apply_system(B, S, ns, rows, on, lam)
