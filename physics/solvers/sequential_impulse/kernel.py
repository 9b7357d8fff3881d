"""The ``sequential_impulse`` step: the rigid contact verbs in Box2D 2.x's order.

The classic rigid-contact solver of Box2D 2.x and Chipmunk (Catto, "Iterative
Dynamics with Temporal Coherence", GDC 2005; "Fast and Simple Physics using
Sequential Impulses", GDC 2006).  One step:

1. contact rows (arms, effective masses, pre-step normal speed, mu);
2. velocities += dt * (gravity + F/m); springs (one impulse, implicit when stiff);
3. warm start: re-apply last step's accumulated impulses (matched by feature
   ids in the narrow phase) -- what makes a tall stack converge in 8 sweeps;
4. ``velocity_iterations`` PGS sweeps: friction clamped to mu * j_n, normal
   impulses clamped >= 0, speculative points may only close their gap;
5. positions += dt * velocities;
6. restitution pass for impacts faster than ``restitution_threshold``
   (v_n' = -e v_n0, after the move as Box2D v3 does, so a speculative hit
   bounces at the surface, not a gap before it);
7. position correction: ``split_impulse`` (pseudo-velocities, ``position_iterations``
   sweeps, no momentum left behind; the default) or ``baumgarte`` (a velocity bias
   in step 4, cheaper, adds some bounce to deep overlaps).

Joints (``J``, ``JW``, ``JS``; None in a world without them, and the kernel is then
compiled without them) are PGS rows too: warm started with the contacts, one
pass after each contact sweep (constraints/joints/table_passes.py), and their
drift removed on the positions after the move by ``joint_position_iterations``
NGS passes (Box2D 2.x's SolvePositionConstraints; with ``joint_solver`` global a
Newton step on each structure's joint equations per pass).
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel
from ...constraints.contact_rigid import contact_bias, restitution_points, solve_points, warm_start_points
from ...constraints.point import prepare_points, zero_impulses
from ...constraints.split_impulse import integrate_pseudo, reset_pseudo, solve_split, zero_rows
from ...constraints.joints.dispatch import store_joints
from ...constraints.joints.pivot import save_pivots
from ...constraints.joints.position import correct_joint_positions
from ...constraints.joints.table_passes import begin_table_joints, table_joint_pass
from ...constraints.springs.substep import solve_springs
from ...store.flat import bodies_view, contacts_view, springs_view
from ...store.optional import optional_joints
from .motion import integrate_positions, integrate_velocities, reset_displacements

GLOBAL = 0  # index of "global" in the joint_solver setting's choices (solvers/joint_settings.py)
BAUMGARTE, SPLIT = 0, 1  # indices of position_correction's choices
# largest push-out speed of the position correction (m/s); Box2D 2.x caps the
# correction at 0.2 m per step, i.e. 12 m/s at 60 Hz
MAX_PUSH = 10.0


@kernel
def si_step(ctx, par, B, C, S, W, M, J, JW, JS):
    """One step (see the module doc); ``W`` point rows, ``M`` motion and pseudo-velocity scratch.
    Returns the number of joints that broke."""
    c = ctx[0]
    p = par[0]
    n = c.n
    nc = c.nc
    dt = c.dt
    inv_dt = p.inv_dt
    prepare_points(B, C, nc, p.stick_speed, W)
    if not p.warm_starting:
        zero_impulses(C, nc)
    integrate_velocities(B, n, c.gx, c.gy, dt)
    if c.ns > 0:
        solve_springs(B, S, c.ns, dt)
    eq_global = p.joint_solver == GLOBAL
    if J is not None:
        begin_table_joints(c, B, J, JW, JS, dt, p.warm_starting)
        save_pivots(c, B, J, JW, M.PV)
    contact_bias(C, nc, W, inv_dt, p.baumgarte, p.linear_slop, MAX_PUSH, p.position_correction == BAUMGARTE)
    warm_start_points(B, C, nc, W)
    for _ in range(p.velocity_iterations):
        solve_points(B, C, nc, W, p.block_solver)
        if J is not None:
            table_joint_pass(c, B, J, JW, JS, inv_dt, eq_global)
    reset_displacements(n, M.DP, M.DQ, M.DC, M.DS)
    integrate_positions(B, n, dt, M.DP, M.DQ, M.DC, M.DS, M.PV, np.int64(n if J is not None else 0))
    # after the move, so a speculative hit bounces at the wall rather than a gap away from it
    restitution_points(B, C, nc, W, p.restitution_threshold)
    if p.position_correction == SPLIT and p.position_iterations > 0:
        reset_pseudo(n, M.VP, M.WP)
        zero_rows(W.jp, nc)
        for _ in range(p.position_iterations):
            solve_split(B, C, nc, W, M.VP, M.WP, W.jp, inv_dt, p.baumgarte, p.linear_slop, MAX_PUSH)
        integrate_pseudo(B, n, dt, M.VP, M.WP)
    broken = 0
    if J is not None:
        if p.joint_position_iterations > 0:
            correct_joint_positions(c, B, J, JW, JS, eq_global, 1.0, p.joint_position_iterations)
        broken = store_joints(c, J, JW, inv_dt)
    return broken


@kernel(entry=True, runtime=True)
def si_step_flat(ctx, par, BF, BI, CF, CI, Cpt, SF, SI, W, M, JF, JI, JW, JS):
    """``si_step`` over the body, contact, spring and joint tables' flat arrays (store/flat.py);
    ``JF`` None: a world without joints."""
    B, C, S = bodies_view(BF, BI), contacts_view(CF, CI, Cpt), springs_view(SF, SI)
    return si_step(ctx, par, B, C, S, W, M, optional_joints(JF, JI), JW, JS)
