"""Force generators of the seed's modes (seed 7.1): gravity, user forces, springs, penalty contacts.

``eval_forces`` fills F (n, 2) and T (n,) for the state (X, Q, V, W) handed
to it, not necessarily the bodies' stored state: Runge-Kutta evaluates the
generators at its intermediate states (the seed asks for springs to be
integrated that way).  Only awake dynamic bodies receive forces.  Springs
are skipped entirely when there are none, and the penalty contact springs
(seed eq. 17) only when the penalty or hybrid mode switches them on.  The
springs' force is constraints/springs/force.py's.
"""
from __future__ import annotations

from ..._jit import kernel
from ...constraints.springs.force import spring_forces
from ...store import DYNAMIC
from .penalty_force import penalty_forces


@kernel
def gravity_and_user(B, n, gx, gy, F, T):
    """F = m g + f_user, T = tau_user for awake dynamic bodies; zero for everything else."""
    for i in range(n):
        if B.kind[i] != DYNAMIC or B.awake[i] == 0:
            F[i, 0] = 0.0
            F[i, 1] = 0.0
            T[i] = 0.0
            continue
        F[i, 0] = B.m[i] * gx + B.f[i, 0]
        F[i, 1] = B.m[i] * gy + B.f[i, 1]
        T[i] = B.tau[i]


@kernel
def eval_forces(c, p, B, S, C, P, R, X, Q, V, W, F, T):
    """All force generators at the state (X, Q, V, W) into F, T (``c`` step context, ``p`` mode
    parameters: ``p.pen`` the penalty parameters, solvers/classic/common.py)."""
    n = c.n
    ns = c.ns
    nc = c.nc
    pen = p.pen
    gravity_and_user(B, n, c.gx, c.gy, F, T)
    if ns > 0:
        spring_forces(S, ns, X, Q, V, W, F, T)
    if pen[0] > 0.0 and nc > 0:
        penalty_forces(B, C, nc, P, X, Q, V, W, R.X0, R.Q0, F, T, pen)
    for i in range(n):  # forces on bodies that may not move are dropped
        if B.kind[i] != DYNAMIC or B.awake[i] == 0:
            F[i, 0] = 0.0
            F[i, 1] = 0.0
            T[i] = 0.0
