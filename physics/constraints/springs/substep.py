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

import numpy as np

from ..._jit import kernel
from . import geometric as geo
from .geometry import EXPLICIT, IMPLICIT, SKIP, movable, rotate, spring_rows
from .implicit import DIAG, JAW, JAX, JAY, JBW, JBX, JBY, RHS, ROW_FIELDS, apply_system, row_speed, solve_system
from .newton import copy_velocities, refine

# explicit while h^2 sum k K (and h sum c K) at the spring's bodies stays below this
# (symplectic Euler is stable to 4: a 16x margin keeps the explicit springs accurate)
_EXPLICIT_LIMIT = 0.25
ROWS_PER_SPRING = 4  # the axis, the transverse row and an angular row per end


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
def _joined(S, ns, cap):
    """(ids, nb): the ``nb`` distinct bodies the springs join, in the order they first appear."""
    ids = np.empty(2 * ns, np.int64)
    seen = np.zeros(cap, np.bool_)
    nb = 0
    for k in range(ns):
        for i in (S.a[k], S.b[k]):
            if i >= 0 and not seen[i]:
                seen[i] = True
                ids[nb] = i
                nb += 1
    return ids, nb


@kernel
def _implicit_rows(B, S, ns, h, G, kinv, kind, stiff_geo, rows, bod, gam, axis, lin):
    """The implicit rows, from the velocities the explicit ones left: the stiff axes first
    (compacted to the front; ``axis``, ``lin`` keep each one's row and stretch), then the stiff
    geometric modes.  Returns (rows, the implicit springs' elastic energy)."""
    nr = np.int64(0)  # not a literal 0: the row kernels compile once, not once more for it
    elastic = 0.0
    for k in range(ns):
        if kind[k] != IMPLICIT:
            continue
        for f in range(ROW_FIELDS):
            axis[k, f] = rows[k, f]
        lin[k] = G[k, geo.STRETCH]
        elastic += 0.5 * S.k[k] * lin[k] * lin[k]
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
    return nr, elastic


@kernel
def _kinetic(B, ids, nb, scale, VE, WE, I0):
    """``scale`` plus the bodies' kinetic energy; their velocities into VE, WE and inverse
    inertias into I0 (what newton.py starts from)."""
    copy_velocities(B, ids, nb, VE, WE)
    for j in range(nb):
        i = ids[j]
        I0[i] = B.inv_i[i]
        if B.inv_m[i] > 0.0:
            scale += 0.5 * (B.v[i, 0] ** 2 + B.v[i, 1] ** 2) / B.inv_m[i]
        if B.inv_i[i] > 0.0:
            scale += 0.5 * B.w[i] ** 2 / B.inv_i[i]
    return scale


@kernel(runtime=True)
def solve_springs(B, S, ns, h):
    """One sub-step h of every spring: explicit impulses for the soft ones, then backward Euler
    on the stiff axes and the stiff geometric modes (see the module doc): solved once linearised
    at the sub-step's start, then to its fixed point on the exact geometry and within the
    rotation cap where that first solve is not it (newton.py)."""
    cap = B.inv_m.shape[0]
    ids, nb = _joined(S, ns, cap)
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
    X0 = np.empty((cap, 2))
    Q0 = np.empty(cap)
    XP = np.empty((cap, 2))
    QP = np.empty(cap)
    RP = np.empty((cap, 2))  # (cos, sin) of QP: once per body, not once per spring end
    for j in range(nb):
        i = ids[j]
        X0[i, 0] = XP[i, 0] = B.x[i, 0]
        X0[i, 1] = XP[i, 1] = B.x[i, 1]
        Q0[i] = QP[i] = B.q[i]
        rotate(RP, i, QP[i])
    spring_rows(B, XP, QP, RP, S, ns, G, rows, bod, kinv, kind)
    _classify(B, S, ns, h, G, kinv, kind, stiff_geo, LK, LC, LG)
    # Hooke + damper (seed eqs. 18-20), explicit, in sequence (symplectic Euler)
    for k in range(ns):
        if kind[k] == EXPLICIT:
            cdot = row_speed(B.v, B.w, rows, bod, k)
            _push(B, rows, bod, k, -h * (S.k[k] * G[k, geo.STRETCH] + S.c[k] * cdot))
    axis = np.zeros((ns, ROW_FIELDS))  # each implicit spring's row as last linearised
    lin = np.zeros(ns)  # ... and its stretch there taken back to x0, C(y) - h J(y) v_y
    nr, elastic = _implicit_rows(B, S, ns, h, G, kinv, kind, stiff_geo, rows, bod, gam, axis, lin)
    if nr == 0:
        return
    VE = np.empty((cap, 2))  # v_e
    WE = np.empty(cap)
    I0 = np.empty(cap)  # the inverse inertias (newton.py holds a body at the rotation cap without)
    scale = _kinetic(B, ids, nb, elastic, VE, WE, I0)  # the step's energy
    lam = np.zeros(nmax)
    solve_system(B, nr, rows, bod, gam, lam)
    apply_system(B, nr, rows, bod, lam)
    refine(B, S, ns, h, ids, nb, X0, Q0, XP, QP, RP, rows, bod, gam, kinv, kind, G, axis, lin, LK, lam, VE, WE, I0,
           scale)
