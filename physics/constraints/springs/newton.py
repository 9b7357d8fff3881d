"""Backward Euler on the stiff springs, solved to its fixed point: Newton's method on the exact
geometry, with the rotation cap as a bound of the minimisation.

Backward Euler is the minimiser of the incremental potential
    Phi(v) = 1/2 |v - v_e|_M^2 + U(x0 + h v)
(v_e the velocities before the implicit rows; Kharevych et al., "Geometric, Variational
Integrators for Computer Animation", SCA 2006; Gast et al., "Optimization Integrator for Large
Time Steps", TVCG 2015).  substep.py solves it once, linearised at the sub-step's start with the
springs' axes and arms frozen; ``refine`` goes on from there where that is not the minimiser:

- the geometry: where the move takes the bodies far across an axis (a large step) the spring
  ends stretched by what the linearisation never saw (a 15 g box released on a 1e4 N/m spring at
  h = 0.2 s stored 1e3 times its energy scale).  While the spring energy where the move takes
  the bodies misses what the linearisation promised by more than NEWTON_TOLERANCE of the step's
  energy, or the last update moved the velocities by more (a fixed point is stationary), the
  rows are linearised again at y = x0 + h v_y, C(x0 + h v) ~ C(y) + h J(y) (v - v_y), with the
  geometric stiffness at y (zero at the fixed point: it only steadies the iteration), and a
  backtracking line search on Phi.  An ordinary step, whose linearisation holds, ends after the
  first check, unchanged.
- the rotation cap: the move turns a body by at most MAX_ROTATION per sub-step
  (constraints/body_rows.py).  Clamping w after the springs were solved broke the solve: the
  linear half of a stiff spring's impulse then moved the anchor alone (a 15 g capsule on a
  1.2e5 N/m spring went from 0.02 J to 985 J in one step).  Here the cap is a bound of the
  minimisation, the box |w_i| h <= MAX_ROTATION, solved by projected Newton (Bertsekas,
  "Projected Newton Methods for Optimization Problems with Simple Constraints", SIAM J. Control
  Optim. 1982): each iterate is projected onto the box, a body at the cap whose Phi would fall
  further outside it is held there for the next Newton step (its inverse inertia out of the
  rows), and the line search runs along the projected path.  For a convex U the minimiser over a
  convex set holding 0 satisfies grad Phi(v*) . (0 - v*) >= 0, which gives
  E(v*) - E(v_e) <= -1/2 |v* - v_e|_M^2: the cap takes energy out, it does not make any.
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from ..rotation_cap import MAX_ROTATION
from . import geometric as geo
from .geometry import IMPLICIT, ends, rotate, spring_rows
from .implicit import DIAG, JAW, JAX, JAY, JBW, JBX, JBY, RHS, ROW_FIELDS, apply_system, row_speed, solve_system

# at most NEWTON_ITERATIONS, while the miss exceeds NEWTON_TOLERANCE of the step's energy (kinetic
# + the implicit springs' elastic energy); LINE_SEARCH halvings of a step that raises Phi
NEWTON_ITERATIONS = 16
NEWTON_TOLERANCE = 1e-4
LINE_SEARCH = 8


@kernel
def _predict(B, ids, nb, X0, Q0, h, XP, QP, RP):
    """Where the bodies are after a move of h with the table's velocities (RP: their rotations)."""
    for j in range(nb):
        i = ids[j]
        XP[i, 0] = X0[i, 0] + h * B.v[i, 0]
        XP[i, 1] = X0[i, 1] + h * B.v[i, 1]
        QP[i] = Q0[i] + h * B.w[i]
        rotate(RP, i, QP[i])


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
def _kinetic_change(B, ids, nb, I0, VK, WK):
    """The kinetic energy of the velocities' change from (VK, WK): from the iterate, or from v_e
    (the first term of Phi)."""
    moved = 0.0
    for j in range(nb):
        i = ids[j]
        if B.inv_m[i] > 0.0:
            moved += 0.5 * ((B.v[i, 0] - VK[i, 0]) ** 2 + (B.v[i, 1] - VK[i, 1]) ** 2) / B.inv_m[i]
        if I0[i] > 0.0:
            moved += 0.5 * (B.w[i] - WK[i]) ** 2 / I0[i]
    return moved


@kernel
def _incremental_potential(B, S, ns, ids, nb, VE, WE, I0, X0, Q0, h, kind, XP, QP, RP):
    """Backward Euler's objective for the implicit springs, Phi(v) = 1/2 |v - v_e|_M^2 +
    sum_k 1/2 k_k C_k(x0 + h v)^2 (v_e the velocities before the implicit solve): its minimiser
    is the backward Euler step."""
    _predict(B, ids, nb, X0, Q0, h, XP, QP, RP)
    phi = _kinetic_change(B, ids, nb, I0, VE, WE)
    for k in range(ns):
        if kind[k] != IMPLICIT:
            continue
        pax, pay, _, _, pbx, pby, _, _ = ends(XP, QP, RP, S, k)
        c = math.hypot(pbx - pax, pby - pay) - S.rest[k]
        phi += 0.5 * S.k[k] * c * c
    return phi


@kernel
def copy_velocities(B, ids, nb, V, W):
    for j in range(nb):
        i = ids[j]
        V[i, 0] = B.v[i, 0]
        V[i, 1] = B.v[i, 1]
        W[i] = B.w[i]


@kernel
def _mismatch(B, S, ns, h, kind, kind_at, axis, lin, G):
    """(miss, floor): how far the spring energy at y (G, from spring_rows) is from what the last
    linearisation promised for the table's velocities, and the rounding floor below which the
    stretch is not known (1e-9 of the length)."""
    miss = 0.0
    floor = 0.0
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
    return miss, floor


@kernel
def _grips(B, S, ns, h, ids, nb, kind, kind_at, G, rows, I0, WE, hold, LK):
    """Which bodies at the cap are held there: where Phi falls outwards,
    dPhi/dw_i = I_i (w_i - w_e,i) + h sum_k T_k J_k,w(i) (T the tension at y), and let go where it
    falls inwards; True if a body changed.  ``LK``: per-body scratch."""
    for j in range(nb):
        LK[ids[j]] = 0.0
    for k in range(ns):
        if kind[k] == IMPLICIT and kind_at[k] == IMPLICIT:
            LK[S.a[k]] += h * G[k, geo.TENSION] * rows[k, JAW]
            if S.b[k] >= 0:
                LK[S.b[k]] += h * G[k, geo.TENSION] * rows[k, JBW]
    w_cap = MAX_ROTATION / h
    regrip = False
    for j in range(nb):
        i = ids[j]
        grip = False
        if I0[i] > 0.0 and abs(B.w[i]) >= w_cap:
            grip = math.copysign(1.0, B.w[i]) * ((B.w[i] - WE[i]) / I0[i] + LK[i]) < 0.0
        if grip != hold[i]:
            hold[i] = grip
            regrip = True
    return regrip


@kernel
def _relinearise(B, S, ns, h, ids, nb, kind, kind_at, G, rows, bod, gam, kinv, axis, lin, XP, QP, RP, VK, WK, VE,
                 WE, hold):
    """The implicit rows linearised at y (the positions XP, QP of the iterate VK, WK), to be
    solved from v_e (a held body's w where it is held, its inverse inertia out of the rows);
    returns the row count."""
    for j in range(nb):
        i = ids[j]
        if hold[i]:
            B.inv_i[i] = 0.0
    spring_rows(B, XP, QP, RP, S, ns, G, rows, bod, kinv, kind_at)
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
    return nr


@kernel
def _line_search(B, S, ns, ids, nb, VE, WE, I0, X0, Q0, h, kind, XP, QP, RP, VK, WK, VN, WN, phi):
    """Along the projected path from the iterate (VK, WK) to Newton's step (VN, WN), halving while
    Phi does not fall; False (the iterate kept) when no halving descends."""
    step = 1.0
    for _halving in range(LINE_SEARCH + 1):
        for j in range(nb):
            i = ids[j]
            B.v[i, 0] = VK[i, 0] + step * (VN[i, 0] - VK[i, 0])
            B.v[i, 1] = VK[i, 1] + step * (VN[i, 1] - VK[i, 1])
            B.w[i] = WK[i] + step * (WN[i] - WK[i])
        _project(B, ids, nb, h, I0)
        if _incremental_potential(B, S, ns, ids, nb, VE, WE, I0, X0, Q0, h, kind, XP, QP, RP) <= phi:
            return True
        step *= 0.5
    for j in range(nb):
        i = ids[j]
        B.v[i, 0] = VK[i, 0]
        B.v[i, 1] = VK[i, 1]
        B.w[i] = WK[i]
    return False


@kernel(runtime=True)
def refine(B, S, ns, h, ids, nb, X0, Q0, XP, QP, RP, rows, bod, gam, kinv, kind, G, axis, lin, LK, lam, VE, WE, I0,
           scale):
    """Newton's iterations from the linearised solve (module doc) over the ``nb`` bodies ``ids``
    the springs join: ``X0, Q0`` their start, ``VE, WE`` the velocities before the implicit rows,
    ``I0`` their inverse inertias, ``scale`` the step's energy; ``axis``, ``lin`` each implicit
    spring's row and stretch as last linearised; ``XP, QP, RP`` the predicted positions, angles
    and rotations; the rest the solve's scratch (substep.py)."""
    cap = B.inv_m.shape[0]
    VK = np.empty((cap, 2))  # the iterate v_y
    WK = np.empty(cap)
    VN = np.empty((cap, 2))  # Newton's full step from it
    WN = np.empty(cap)
    hold = np.zeros(cap, np.bool_)
    kind_at = np.zeros(ns, np.int8)  # the springs' kinds at y
    moved = 0.0  # the kinetic energy of the last Newton update (the first solve is not one)
    for _newton in range(NEWTON_ITERATIONS):
        clipped = _project(B, ids, nb, h, I0)
        # the stretch where the move takes the bodies, against what the linearisation promised
        _predict(B, ids, nb, X0, Q0, h, XP, QP, RP)
        spring_rows(B, XP, QP, RP, S, ns, G, rows, bod, kinv, kind_at)
        miss, floor = _mismatch(B, S, ns, h, kind, kind_at, axis, lin, G)
        regrip = _grips(B, S, ns, h, ids, nb, kind, kind_at, G, rows, I0, WE, hold, LK)
        tol = NEWTON_TOLERANCE * scale + floor
        if not clipped and not regrip and not miss > tol and not moved > tol:
            break
        phi = _incremental_potential(B, S, ns, ids, nb, VE, WE, I0, X0, Q0, h, kind, XP, QP, RP)
        copy_velocities(B, ids, nb, VK, WK)
        nr = _relinearise(B, S, ns, h, ids, nb, kind, kind_at, G, rows, bod, gam, kinv, axis, lin, XP, QP, RP, VK,
                          WK, VE, WE, hold)
        solve_system(B, nr, rows, bod, gam, lam)
        apply_system(B, nr, rows, bod, lam)
        for j in range(nb):
            B.inv_i[ids[j]] = I0[ids[j]]
        copy_velocities(B, ids, nb, VN, WN)
        if not _line_search(B, S, ns, ids, nb, VE, WE, I0, X0, Q0, h, kind, XP, QP, RP, VK, WK, VN, WN, phi):
            break  # no descent along Newton's direction: v_y stays
        moved = _kinetic_change(B, ids, nb, I0, VK, WK)
    for j in range(nb):
        B.inv_i[ids[j]] = I0[ids[j]]
