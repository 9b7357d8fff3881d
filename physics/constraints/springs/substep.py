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
from ..body_rows import MAX_ROTATION
from ..point import cross
from . import geometric as geo
from .geometry import anchor, movable
from .implicit import DIAG, JAW, JAX, JAY, JBW, JBX, JBY, RHS, ROW_FIELDS, apply_system, row_speed, solve_system

# explicit while h^2 sum k K (and h sum c K) at the spring's bodies stays below this
# (symplectic Euler is stable to 4: a 16x margin keeps the explicit springs accurate)
_EXPLICIT_LIMIT = 0.25
# Newton iterations on backward Euler's geometry (solve_springs): at most this many, while the
# spring energy where the move takes the bodies misses the linearisation's by more than
# NEWTON_TOLERANCE of the step's energy (kinetic + the implicit springs' elastic energy);
# LINE_SEARCH halvings of a Newton step that would raise the incremental potential
NEWTON_ITERATIONS = 16
NEWTON_TOLERANCE = 1e-4
LINE_SEARCH = 8
SKIP, EXPLICIT, IMPLICIT = 0, 1, 2
ROWS_PER_SPRING = 4  # the axis, the transverse row and an angular row per end


@kernel
def _geometry(B, X, Q, S, ns, G, rows, bod, kinv, kind):
    """Axis, arms, length, stretch and tension (G), the axis row (rows[k], K in kinv) of every
    spring with the bodies at positions ``X`` and angles ``Q`` (the velocities are the table's);
    SKIP where the axis is undefined or the spring exerts nothing."""
    for k in range(ns):
        kind[k] = SKIP
        a = S.a[k]
        b = S.b[k]
        pax, pay, rax, ray = anchor(X, Q, a, S.la[k, 0], S.la[k, 1])
        if b >= 0:
            pbx, pby, rbx, rby = anchor(X, Q, b, S.lb[k, 0], S.lb[k, 1])
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


@kernel
def _predict(B, ids, nb, X0, Q0, h, XP, QP):
    """Where the bodies are after a move of h with the table's velocities."""
    for j in range(nb):
        i = ids[j]
        XP[i, 0] = X0[i, 0] + h * B.v[i, 0]
        XP[i, 1] = X0[i, 1] + h * B.v[i, 1]
        QP[i] = Q0[i] + h * B.w[i]


@kernel
def _project(B, ids, nb, h, I0):
    """The velocities onto the rotation cap's box |w| h <= MAX_ROTATION (bodies that turn as
    they are told, without inverse inertia, are left to the move's cap); True if one moved."""
    moved = False
    for j in range(nb):
        i = ids[j]
        if I0[i] > 0.0 and abs(B.w[i]) > MAX_ROTATION / h:
            B.w[i] = math.copysign(MAX_ROTATION / h, B.w[i])
            moved = True
    return moved


@kernel
def _incremental_potential(B, S, ns, ids, nb, VE, WE, I0, X0, Q0, h, kind, XP, QP):
    """Backward Euler's objective for the implicit springs, Phi(v) = 1/2 |v - v_e|_M^2 +
    sum_k 1/2 k_k C_k(x0 + h v)^2 (v_e the velocities before the implicit solve): its minimiser
    is the backward Euler step."""
    _predict(B, ids, nb, X0, Q0, h, XP, QP)
    phi = 0.0
    for j in range(nb):
        i = ids[j]
        if B.inv_m[i] > 0.0:
            phi += 0.5 * ((B.v[i, 0] - VE[i, 0]) ** 2 + (B.v[i, 1] - VE[i, 1]) ** 2) / B.inv_m[i]
        if I0[i] > 0.0:
            phi += 0.5 * (B.w[i] - WE[i]) ** 2 / I0[i]
    for k in range(ns):
        if kind[k] != IMPLICIT:
            continue
        a = S.a[k]
        b = S.b[k]
        pax, pay, _, _ = anchor(XP, QP, a, S.la[k, 0], S.la[k, 1])
        if b >= 0:
            pbx, pby, _, _ = anchor(XP, QP, b, S.lb[k, 0], S.lb[k, 1])
        else:
            pbx, pby = S.lb[k, 0], S.lb[k, 1]
        c = math.hypot(pbx - pax, pby - pay) - S.rest[k]
        phi += 0.5 * S.k[k] * c * c
    return phi


@kernel
def _copy_velocities(B, ids, nb, V, W):
    for j in range(nb):
        i = ids[j]
        V[i, 0] = B.v[i, 0]
        V[i, 1] = B.v[i, 1]
        W[i] = B.w[i]


@kernel(runtime=True)
def solve_springs(B, S, ns, h):
    """One sub-step h of every spring: explicit impulses for the soft ones, then backward Euler
    on the stiff axes and the stiff geometric modes (see the module doc).

    Backward Euler is the minimiser of the incremental potential
        Phi(v) = 1/2 |v - v_e|_M^2 + U(x0 + h v)
    (v_e the velocities before the implicit rows; e.g. Kharevych et al., "Geometric,
    Variational Integrators for Computer Animation", SCA 2006; Gast et al., "Optimization
    Integrator for Large Time Steps", TVCG 2015).  Two things stood between the solve and it:

    - the geometry: the rows are the springs linearised at the sub-step's start, their axes and
      arms frozen.  Where the move takes the bodies far across an axis (a large step) the spring
      ends stretched by what the linearisation never saw: a 15 g box released on a 1e4 N/m spring
      at h = 0.2 s stored 1e3 times its energy scale.  So, while the spring energy where the move
      takes the bodies misses what the linearisation promised by more than NEWTON_TOLERANCE of
      the step's energy, or its last update moved the velocities by more (kinetic energy of the
      change: a fixed point is stationary), Newton's method goes on: the rows again, linearised at y = x0 + h v_y,
      C(x0 + h v) ~ C(y) + h J(y) (v - v_y), with the geometric stiffness at y (zero at the fixed
      point: they only steady the iteration), and a backtracking line search on Phi.  The first
      solve is the linearised one as before, so an ordinary step, whose linearisation holds, ends
      there unchanged.
    - the rotation cap: the move turns a body by at most MAX_ROTATION per sub-step
      (constraints/body_rows.py).  Clamping w after the springs were solved broke the solve: the
      linear half of a stiff spring's impulse then moved the anchor alone (a 15 g capsule on a
      1.2e5 N/m spring went from 0.02 J to 985 J in one step).  Here the cap is a bound of the
      minimisation, the box |w_i| h <= MAX_ROTATION, solved by projected Newton (Bertsekas,
      "Projected Newton Methods for Optimization Problems with Simple Constraints", SIAM J.
      Control Optim. 1982): each iterate is projected onto the box, a body at the cap whose Phi
      would fall further outside it is held there for the next Newton step (its inverse inertia
      out of the rows), and the line search runs along the projected path.  For a convex U the
      minimiser over a convex set holding 0 satisfies grad Phi(v*) . (0 - v*) >= 0, which gives
      E(v*) - E(v_e) <= -1/2 |v* - v_e|_M^2: the cap takes energy out, it does not make any."""
    cap = B.inv_m.shape[0]
    ids = np.empty(2 * ns, np.int64)
    seen = np.zeros(cap, np.bool_)
    nb = 0
    for k in range(ns):
        for i in (S.a[k], S.b[k]):
            if i >= 0 and not seen[i]:
                seen[i] = True
                ids[nb] = i
                nb += 1
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
    for j in range(nb):
        i = ids[j]
        X0[i, 0] = B.x[i, 0]
        X0[i, 1] = B.x[i, 1]
        Q0[i] = B.q[i]
        XP[i, 0] = X0[i, 0]
        XP[i, 1] = X0[i, 1]
        QP[i] = Q0[i]
    _geometry(B, XP, QP, S, ns, G, rows, bod, kinv, kind)
    _classify(B, S, ns, h, G, kinv, kind, stiff_geo, LK, LC, LG)
    # Hooke + damper (seed eqs. 18-20), explicit, in sequence (symplectic Euler)
    for k in range(ns):
        if kind[k] == EXPLICIT:
            cdot = row_speed(B.v, B.w, rows, bod, k)
            _push(B, rows, bod, k, -h * (S.k[k] * G[k, geo.STRETCH] + S.c[k] * cdot))
    # the implicit rows together, from the velocities the explicit ones left: the stiff axes
    # first (compacted to the front), then the stiff geometric modes
    axis = np.zeros((ns, ROW_FIELDS))  # each implicit spring's row as last linearised
    lin = np.zeros(ns)  # ... and its stretch there taken back to x0, C(y) - h J(y) v_y
    nr = np.int64(0)  # not a literal 0: the row kernels compile once, not once more for it
    scale = 0.0  # the step's energy: kinetic (below) + the implicit springs' elastic
    for k in range(ns):
        if kind[k] != IMPLICIT:
            continue
        for f in range(ROW_FIELDS):
            axis[k, f] = rows[k, f]
        lin[k] = G[k, geo.STRETCH]
        scale += 0.5 * S.k[k] * lin[k] * lin[k]
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
    VE = np.empty((cap, 2))  # v_e
    WE = np.empty(cap)
    VK = np.empty((cap, 2))  # the iterate v_y
    WK = np.empty(cap)
    VN = np.empty((cap, 2))  # Newton's full step from it
    WN = np.empty(cap)
    I0 = np.empty(cap)  # the inverse inertias (a held body's is taken out of the rows)
    hold = np.zeros(cap, np.bool_)
    kind_at = np.zeros(ns, np.int8)  # the springs' kinds at y
    _copy_velocities(B, ids, nb, VE, WE)
    for j in range(nb):
        i = ids[j]
        I0[i] = B.inv_i[i]
        if B.inv_m[i] > 0.0:
            scale += 0.5 * (B.v[i, 0] ** 2 + B.v[i, 1] ** 2) / B.inv_m[i]
        if B.inv_i[i] > 0.0:
            scale += 0.5 * B.w[i] ** 2 / B.inv_i[i]
    lam = np.zeros(nmax)
    solve_system(B, nr, rows, bod, gam, lam)
    apply_system(B, nr, rows, bod, lam)
    w_cap = MAX_ROTATION / h
    moved = 0.0  # the kinetic energy of the last Newton update (the first solve is not one)
    for _newton in range(NEWTON_ITERATIONS):
        clipped = _project(B, ids, nb, h, I0)
        # the stretch where the move takes the bodies, against what the linearisation promised
        _predict(B, ids, nb, X0, Q0, h, XP, QP)
        _geometry(B, XP, QP, S, ns, G, rows, bod, kinv, kind_at)
        miss = 0.0
        floor = 0.0  # rounding: the stretch known to 1e-9 of the length
        for k in range(ns):
            if kind[k] == IMPLICIT and kind_at[k] == IMPLICIT:
                a = S.a[k]
                promised = lin[k] + h * (axis[k, JAX] * B.v[a, 0] + axis[k, JAY] * B.v[a, 1]
                                         + axis[k, JAW] * B.w[a])
                b = S.b[k]
                if b >= 0:
                    promised += h * (axis[k, JBX] * B.v[b, 0] + axis[k, JBY] * B.v[b, 1] + axis[k, JBW] * B.w[b])
                miss += 0.5 * S.k[k] * abs(G[k, geo.STRETCH] ** 2 - promised ** 2)
                floor += 0.5 * S.k[k] * (1e-9 * G[k, geo.LEN]) ** 2
        # at the cap: held where Phi falls outwards, dPhi/dw_i = I_i (w_i - w_e,i) + h sum_k T_k J_k,w(i)
        # (T the tension at y), let go where it falls inwards
        for j in range(nb):
            LK[ids[j]] = 0.0
        for k in range(ns):
            if kind[k] == IMPLICIT and kind_at[k] == IMPLICIT:
                LK[S.a[k]] += h * G[k, geo.TENSION] * rows[k, JAW]
                if S.b[k] >= 0:
                    LK[S.b[k]] += h * G[k, geo.TENSION] * rows[k, JBW]
        regrip = False
        for j in range(nb):
            i = ids[j]
            grip = False
            if I0[i] > 0.0 and abs(B.w[i]) >= w_cap:
                grip = math.copysign(1.0, B.w[i]) * ((B.w[i] - WE[i]) / I0[i] + LK[i]) < 0.0
            if grip != hold[i]:
                hold[i] = grip
                regrip = True
        tol = NEWTON_TOLERANCE * scale + floor
        if not clipped and not regrip and not miss > tol and not moved > tol:
            break
        phi = _incremental_potential(B, S, ns, ids, nb, VE, WE, I0, X0, Q0, h, kind, XP, QP)
        # Newton: the rows linearised at y, from v_e (a held body's w where it is held)
        _copy_velocities(B, ids, nb, VK, WK)
        for j in range(nb):
            i = ids[j]
            B.inv_i[i] = 0.0 if hold[i] else I0[i]
        _geometry(B, XP, QP, S, ns, G, rows, bod, kinv, kind_at)
        for j in range(nb):
            i = ids[j]
            B.v[i, 0] = VE[i, 0]
            B.v[i, 1] = VE[i, 1]
            B.w[i] = WK[i] if hold[i] else WE[i]
        nr = np.int64(0)
        for k in range(ns):
            if kind[k] != IMPLICIT or kind_at[k] != IMPLICIT:
                continue
            for f in range(ROW_FIELDS):
                axis[k, f] = rows[k, f]
            if nr != k:
                for f in range(rows.shape[1]):
                    rows[nr, f] = rows[k, f]
                bod[nr, 0] = bod[k, 0]
                bod[nr, 1] = bod[k, 1]
            lin[k] = G[k, geo.STRETCH] - h * row_speed(VK, WK, rows, bod, nr)
            g = 1.0 / (h * (S.c[k] + h * S.k[k]))
            gam[nr] = g
            rows[nr, DIAG] = kinv[k] + g
            rows[nr, RHS] = -(row_speed(B.v, B.w, rows, bod, nr) + lin[k] * h * S.k[k] * g)
            nr += 1
        first_geo = nr
        for k in range(ns):
            if kind[k] == IMPLICIT and kind_at[k] == IMPLICIT:
                nr = geo.add_rows(B, S, k, G, h, rows, bod, gam, nr)
        for r in range(first_geo, nr):  # zero violation at y: rhs -J (v_e - v_y)
            rows[r, RHS] += row_speed(VK, WK, rows, bod, r)
        solve_system(B, nr, rows, bod, gam, lam)
        apply_system(B, nr, rows, bod, lam)
        for j in range(nb):
            B.inv_i[ids[j]] = I0[ids[j]]
        # along the projected path, halving the step while Phi does not fall
        _copy_velocities(B, ids, nb, VN, WN)
        step = 1.0
        descent = False
        for _halving in range(LINE_SEARCH + 1):
            for j in range(nb):
                i = ids[j]
                B.v[i, 0] = VK[i, 0] + step * (VN[i, 0] - VK[i, 0])
                B.v[i, 1] = VK[i, 1] + step * (VN[i, 1] - VK[i, 1])
                B.w[i] = WK[i] + step * (WN[i] - WK[i])
            _project(B, ids, nb, h, I0)
            if _incremental_potential(B, S, ns, ids, nb, VE, WE, I0, X0, Q0, h, kind, XP, QP) <= phi:
                descent = True
                break
            step *= 0.5
        if not descent:  # no descent along Newton's direction: v_y stays
            for j in range(nb):
                i = ids[j]
                B.v[i, 0] = VK[i, 0]
                B.v[i, 1] = VK[i, 1]
                B.w[i] = WK[i]
            break
        moved = 0.0
        for j in range(nb):
            i = ids[j]
            if B.inv_m[i] > 0.0:
                moved += 0.5 * ((B.v[i, 0] - VK[i, 0]) ** 2 + (B.v[i, 1] - VK[i, 1]) ** 2) / B.inv_m[i]
            if I0[i] > 0.0:
                moved += 0.5 * (B.w[i] - WK[i]) ** 2 / I0[i]
    for j in range(nb):
        B.inv_i[ids[j]] = I0[ids[j]]
