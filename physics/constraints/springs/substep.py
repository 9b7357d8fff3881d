"""Springs inside the sub-stepped solvers (soft_step, sequential_impulse): impulses on velocities.

A spring with stiffness k and damping c between anchors is applied as an
impulse along its axis each sub-step.  While the spring is soft for the
bodies it joins, the explicit symplectic impulse -h (k C + c dC/dt) is
accurate and conserves energy well.  Beyond that it would blow up, so the
spring switches to the implicit (soft constraint) form of Catto's "Soft
Constraints" (GDC 2011):
  gamma = 1 / (h (c + h k)),  bias = C h k gamma,
which is backward Euler on the spring.  All implicit rows are solved
together as one linear system (constraints/springs/implicit.py): solved one
by one in a single pass, a chain of light links carrying a heavy load only
passes on part of the load each sub-step and swings far beyond its stretch.

Explicit or implicit is decided per spring from the stiffness of every spring
at its two bodies, not the spring alone: symplectic Euler is stable while
h^2 lambda_max(W K) < 4, and lambda_max is bounded by the row sums
(Gershgorin) sum_s k_s K_s over the springs sharing a body, so a light body
held by many springs goes implicit even if each spring alone is soft.  The
same test, on the geometric stiffness of the turning axis and arms
(geometric.py), decides whether a spring's geometric rows join the system.
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from ..point import cross
from . import geometric as geo
from .geometry import anchor, movable
from .implicit import DIAG, JAW, JAX, JAY, JBW, JBX, JBY, RHS, ROW_FIELDS, apply_system, row_speed, solve_system

# explicit while h^2 sum k K (and h sum c K) at the spring's bodies stays below this
# (symplectic Euler is stable to 4: a 16x margin keeps the explicit springs accurate)
_EXPLICIT_LIMIT = 0.25
SKIP, EXPLICIT, IMPLICIT = 0, 1, 2
ROWS_PER_SPRING = 4  # the axis, the transverse row and an angular row per end


@kernel
def _geometry(B, S, ns, G, rows, bod, kinv, kind):
    """Axis, arms, length, stretch and tension (G), the axis row (rows[k], K in kinv) of every
    spring; SKIP where the axis is undefined or the spring exerts nothing."""
    for k in range(ns):
        kind[k] = SKIP
        a = S.a[k]
        b = S.b[k]
        pax, pay, rax, ray = anchor(B.x, B.q, a, S.la[k, 0], S.la[k, 1])
        if b >= 0:
            pbx, pby, rbx, rby = anchor(B.x, B.q, b, S.lb[k, 0], S.lb[k, 1])
        else:
            pbx, pby, rbx, rby = S.lb[k, 0], S.lb[k, 1], 0.0, 0.0
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


@kernel
def _classify(B, S, ns, h, G, kinv, kind, stiff_geo, LK, LC, LG):
    """EXPLICIT where h^2 sum k K and h sum c K over the springs at both bodies stay small;
    ``stiff_geo`` where h^2 sum trace(W K_geo) there does not."""
    for k in range(ns):
        for i in (S.a[k], S.b[k]):
            if i >= 0:
                LK[i] = 0.0
                LC[i] = 0.0
                LG[i] = 0.0
    for k in range(ns):
        if kind[k] == SKIP:
            continue
        g = geo.rate(B, S, k, G)
        for i in (S.a[k], S.b[k]):
            if movable(B, i):
                LK[i] += S.k[k] * kinv[k]
                LC[i] += S.c[k] * kinv[k]
                LG[i] += g
    for k in range(ns):
        stiff_geo[k] = False
        if kind[k] == SKIP:
            continue
        a = S.a[k]
        b = S.b[k]
        both = movable(B, a) and movable(B, b)
        # row sum of this spring: its own k K once, plus its neighbours' at either end
        lk = LK[a] + (LK[b] if movable(B, b) else 0.0)
        lc = LC[a] + (LC[b] if movable(B, b) else 0.0)
        lg = LG[a] + (LG[b] if movable(B, b) else 0.0)
        if both:
            lk -= S.k[k] * kinv[k]
            lc -= S.c[k] * kinv[k]
            lg -= geo.rate(B, S, k, G)
        if lk * h * h < _EXPLICIT_LIMIT and lc * h < _EXPLICIT_LIMIT:
            kind[k] = EXPLICIT
        stiff_geo[k] = lg * h * h >= _EXPLICIT_LIMIT


@kernel
def _push(B, rows, bod, k, j):
    """Impulse j along row k (+j on b along +u, -j on a)."""
    a = bod[k, 0]
    b = bod[k, 1]
    B.v[a, 0] += B.inv_m[a] * j * rows[k, JAX]
    B.v[a, 1] += B.inv_m[a] * j * rows[k, JAY]
    B.w[a] += B.inv_i[a] * j * rows[k, JAW]
    if b >= 0:
        B.v[b, 0] += B.inv_m[b] * j * rows[k, JBX]
        B.v[b, 1] += B.inv_m[b] * j * rows[k, JBY]
        B.w[b] += B.inv_i[b] * j * rows[k, JBW]


@kernel(runtime=True)
def solve_springs(B, S, ns, h):
    """One sub-step h of every spring: explicit impulses for the soft ones, then one implicit
    system for the stiff axes and the stiff geometric modes (see the module doc)."""
    cap = B.inv_m.shape[0]
    nmax = ROWS_PER_SPRING * ns
    rows = np.zeros((nmax, ROW_FIELDS))
    bod = np.full((nmax, 2), -1, np.int64)
    gam = np.zeros(nmax)
    G = np.zeros((ns, geo.GEO_FIELDS))
    kinv = np.zeros(ns)
    kind = np.zeros(ns, np.int8)
    stiff_geo = np.zeros(ns, np.bool_)
    LK = np.empty(cap)
    LC = np.empty(cap)
    LG = np.empty(cap)
    _geometry(B, S, ns, G, rows, bod, kinv, kind)
    _classify(B, S, ns, h, G, kinv, kind, stiff_geo, LK, LC, LG)
    # Hooke + damper (seed eqs. 18-20), explicit, in sequence (symplectic Euler)
    for k in range(ns):
        if kind[k] == EXPLICIT:
            cdot = row_speed(B.v, B.w, rows, bod, k)
            _push(B, rows, bod, k, -h * (S.k[k] * G[k, geo.STRETCH] + S.c[k] * cdot))
    # the implicit rows together, from the velocities the explicit ones left: the stiff axes
    # first (compacted to the front), then the stiff geometric modes
    nr = np.int64(0)  # not a literal 0: the row kernels compile once, not once more for it
    for k in range(ns):
        if kind[k] != IMPLICIT:
            continue
        if nr != k:  # element by element: an array assignment brings numba's shape-error code along
            for f in range(rows.shape[1]):
                rows[nr, f] = rows[k, f]
            bod[nr, 0] = bod[k, 0]
            bod[nr, 1] = bod[k, 1]
        g = 1.0 / (h * (S.c[k] + h * S.k[k]))
        gam[nr] = g
        rows[nr, DIAG] = kinv[k] + g
        rows[nr, RHS] = -(row_speed(B.v, B.w, rows, bod, nr) + G[k, geo.STRETCH] * h * S.k[k] * g)
        nr += 1
    for k in range(ns):
        if stiff_geo[k]:
            nr = geo.add_rows(B, S, k, G, h, rows, bod, gam, nr)
    if nr == 0:
        return
    lam = np.zeros(nr)
    solve_system(B, nr, rows, bod, gam, lam)
    apply_system(B, nr, rows, bod, lam)
