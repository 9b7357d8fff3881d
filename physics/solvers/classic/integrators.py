"""Integrators for the force generators: explicit Euler, symplectic Euler, RK4.

State per body: x, q (angle), v, w.  Awake dynamic bodies move under forces,
kinematic bodies move with their velocity, static bodies never move.

- ``euler``: the real explicit Euler: x' = x + h v, v' = v + h a(x, v), both
  from the old state.  An undamped oscillator gains energy by (1 + (omega h)^2)
  every step.
- ``symplectic_euler``: v' = v + h a(x, v), x' = x + h v' (semi-implicit; bounded
  energy error).
- ``rk4``: classical Runge-Kutta; the force generators are evaluated at the
  four intermediate states (seed 7.1-7.2).  Exact for constant gravity.

``advance`` runs ``substeps`` sub-steps of one method.  ``substeps_for`` picks
the count that keeps omega h inside the method's stability range (LIMITS)
for the stiffest spring.
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np

from ..._jit import kernel
from ...constraints.joints.table_passes import classic_joint_substep
from ...options import INTEGRATORS
from ...store import DYNAMIC, KINEMATIC
from .forces import eval_forces
from .penalty_force import update_stick

METHODS = {name: INTEGRATORS.index(name) for name in INTEGRATORS}  # euler 0, symplectic 1, rk4 2
# largest omega h allowed per sub-step.  Symplectic Euler is stable below 2, RK4
# below 2.83 (half of each, for damping and accuracy).  Explicit Euler is never stable
# for an undamped spring; 0.2 bounds its energy gain to 4 % per sub-step.
LIMITS = {"euler": 0.2, "symplectic_euler": 1.0, "rk4": 1.4}

# X0, Q0: state at the step start; XS..WS: a stage state; F, T: forces;
# AX..AW: RK4 sums; VP, WP: velocities before the contact response; IMP: bodies hit
# by an impact this step (int8)
Work = namedtuple("Work", "X0 Q0 XS QS VS WS F T AX AQ AV AW VP WP IMP")


def allocate_work(cap: int) -> Work:
    vec = ("X0", "XS", "VS", "F", "AX", "AV", "VP")
    return Work(**{k: (np.zeros((cap, 2)) if k in vec else
                       np.zeros(cap, dtype=np.int8) if k == "IMP" else np.zeros(cap))
                   for k in Work._fields})


@kernel
def moves(B, i):
    return B.kind[i] == KINEMATIC or (B.kind[i] == DYNAMIC and B.awake[i] == 1)


@kernel
def save_start(B, n, R):
    for i in range(n):
        R.X0[i, 0] = B.x[i, 0]
        R.X0[i, 1] = B.x[i, 1]
        R.Q0[i] = B.q[i]


@kernel
def euler(c, p, B, S, C, P, R, h):
    eval_forces(c, p, B, S, C, P, R, B.x, B.q, B.v, B.w, R.F, R.T)
    for i in range(c.n):
        if not moves(B, i):
            continue
        B.x[i, 0] += h * B.v[i, 0]  # old velocity: explicit
        B.x[i, 1] += h * B.v[i, 1]
        B.q[i] += h * B.w[i]
        B.v[i, 0] += h * B.inv_m[i] * R.F[i, 0]
        B.v[i, 1] += h * B.inv_m[i] * R.F[i, 1]
        B.w[i] += h * B.inv_i[i] * R.T[i]


@kernel
def symplectic_euler(c, p, B, S, C, P, R, h):
    eval_forces(c, p, B, S, C, P, R, B.x, B.q, B.v, B.w, R.F, R.T)
    for i in range(c.n):
        if not moves(B, i):
            continue
        B.v[i, 0] += h * B.inv_m[i] * R.F[i, 0]
        B.v[i, 1] += h * B.inv_m[i] * R.F[i, 1]
        B.w[i] += h * B.inv_i[i] * R.T[i]
        B.x[i, 0] += h * B.v[i, 0]  # new velocity: semi-implicit
        B.x[i, 1] += h * B.v[i, 1]
        B.q[i] += h * B.w[i]


@kernel
def _copy_state(B, n, R):
    for i in range(n):
        R.XS[i, 0] = B.x[i, 0]
        R.XS[i, 1] = B.x[i, 1]
        R.QS[i] = B.q[i]
        R.VS[i, 0] = B.v[i, 0]
        R.VS[i, 1] = B.v[i, 1]
        R.WS[i] = B.w[i]
        R.AX[i, 0] = R.AX[i, 1] = R.AQ[i] = 0.0
        R.AV[i, 0] = R.AV[i, 1] = R.AW[i] = 0.0


@kernel
def rk4(c, p, B, S, C, P, R, h):
    n = c.n
    _copy_state(B, n, R)
    for st in range(4):
        eval_forces(c, p, B, S, C, P, R, R.XS, R.QS, R.VS, R.WS, R.F, R.T)
        wgt = 1.0 if st == 0 or st == 3 else 2.0
        f = h * (0.5 if st < 2 else 1.0)
        for i in range(n):
            if not moves(B, i):
                continue
            dx = R.VS[i, 0]
            dy = R.VS[i, 1]
            dq = R.WS[i]
            ax = B.inv_m[i] * R.F[i, 0]
            ay = B.inv_m[i] * R.F[i, 1]
            aw = B.inv_i[i] * R.T[i]
            R.AX[i, 0] += wgt * dx
            R.AX[i, 1] += wgt * dy
            R.AQ[i] += wgt * dq
            R.AV[i, 0] += wgt * ax
            R.AV[i, 1] += wgt * ay
            R.AW[i] += wgt * aw
            if st < 3:
                R.XS[i, 0] = B.x[i, 0] + f * dx
                R.XS[i, 1] = B.x[i, 1] + f * dy
                R.QS[i] = B.q[i] + f * dq
                R.VS[i, 0] = B.v[i, 0] + f * ax
                R.VS[i, 1] = B.v[i, 1] + f * ay
                R.WS[i] = B.w[i] + f * aw
    s = h / 6.0
    for i in range(n):
        if not moves(B, i):
            continue
        B.x[i, 0] += s * R.AX[i, 0]
        B.x[i, 1] += s * R.AX[i, 1]
        B.q[i] += s * R.AQ[i]
        B.v[i, 0] += s * R.AV[i, 0]
        B.v[i, 1] += s * R.AV[i, 1]
        B.w[i] += s * R.AW[i]


@kernel
def advance(c, p, B, S, C, P, R, J, JW, JS):
    """``p.substeps`` steps of the integrator ``c.integrator``; penalty stick springs updated after each,
    and the joints' velocity passes (``J`` None: a world without joints, compiled without them)."""
    substeps = p.substeps
    method = c.integrator
    pen = p.pen
    h = c.dt / substeps
    if pen[0] > 0.0:
        # penalty points report F h summed over this step's sub-steps (update_stick); impulse
        # points are zeroed again when the impulses start (impulses.activate_impulses)
        C.jn[: c.nc] = 0.0
        C.jt[: c.nc] = 0.0
    for _ in range(substeps):
        if method == 0:
            euler(c, p, B, S, C, P, R, h)
        elif method == 1:
            symplectic_euler(c, p, B, S, C, P, R, h)
        else:
            rk4(c, p, B, S, C, P, R, h)
        if pen[0] > 0.0 and c.nc > 0:
            update_stick(B, C, c.nc, P, R, h, pen)
        if J is not None:
            classic_joint_substep(c, B, J, JW, JS, h, p.joint_iterations, p.joint_solver == 0)


def substeps_for(rate: float, dt: float, method: str) -> int:
    """Sub-steps so that rate * h stays within the method's limit."""
    return max(1, int(math.ceil(rate * dt / LIMITS[method] - 1e-9)))
