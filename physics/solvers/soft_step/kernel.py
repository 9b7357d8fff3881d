"""The ``soft_step`` step: the constraint verbs in Box2D v3's order (solver.c, b2SolverStage).

Per step: contact rows are prepared once; then for each of N sub-steps:
integrate velocities, warm start, solve contacts softly (with bias), springs,
integrate positions, relax (solve again without bias so the push-out leaves no
velocity behind), restitution for the points that first touched in this
sub-step (constraints/contact_restitution.py; Box2D bounces once per step,
after the last sub-step, at the speed the step began with).  Finally the
impulses are stored for the next step's warm start.  Sub-stepping gives the stiffness of a small
time step at the price of one narrow phase per step (Catto, "Solver2D", 2024).

Springs come last before the move, after the contacts and joints: a stiff spring is solved
implicitly (constraints/springs/substep.py) so that its stretch after the move is what it
allows, and a velocity that a later row adds along it is stored as 1/2 k (v h)^2, k h^2 / m
times that velocity's kinetic energy.  Solved first, the contacts that followed moved a 15 g
capsule on a 1.2e5 N/m spring against it (k h^2 / m = 2.7e5 at dt 0.74 s) and a step went from
1.5 J to 1360 J (tests/test_spinning_capsule_on_chain.py); solved last, it ends with 0.2 J.
A contact the spring then pushes into is pushed out again in the next sub-step, at most at
push_out_speed.

Joints (``J`` the joint table, ``JW`` their scratch, ``JS`` the global system;
physics/constraints/joints) are solved after the contacts in each pass, so the
equality rows hold exactly at the end of a sub-step when they are solved as one
system (``joint_solver`` "global"); with ``joint_projection`` each sub-step's
move is followed by one Newton step on the positions of the globally solved
structures, and the relax pass then makes the velocities consistent with the
projected positions (RATTLE's order, Andersen 1983).  It holds the joints
exactly (a 30-link chain whipping for 10 s: 0 mm against 3.4 mm) but removes
energy: the relax pass takes out the velocity across the projected constraint
(a double pendulum lost 30 % of its energy in 10 s; projecting once per step
instead, 26 %), so it is off by default.  A world without joints passes None for all three and the kernel is
compiled without them; one without springs passes None for ``S`` (store/optional.py).
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel
from ...constraints.body_rows import (gather_bodies, integrate_row_positions, integrate_row_velocities,
                                      load_velocities, store_velocities)
from ...constraints.contact_restitution import restitution_contacts
from ...constraints.contact_soft import prepare_contacts, solve_contacts, store_impulses, warm_start_contacts
from ...constraints.joints.dispatch import (project_joints, refresh_rows, solve_joints, store_joints,
                                            warm_start_joints)
from ...constraints.joints.prepare import prepare_joints, zero_joint_impulses
from ...constraints.joints.pivot import save_pivots
from ...constraints.rotation_cap import PIVOT_COLUMNS
from ...constraints.joints.sync import save_start
from ...constraints.point import zero_impulses
from ...constraints.restitution_cluster import save_velocities
from ...constraints.springs.substep import solve_springs
from ...store.flat import bodies_view, contacts_view
from ...store.optional import optional_joints, optional_springs

GLOBAL = 0  # index of "global" in the joint_solver setting's choices


@kernel
def soft_step(ctx, par, B, C, S, R, SB, J, JW, JS, V0):
    # (JW.SB is SB: the joints work on the same body rows as the contacts)
    """One step of ``ctx[0].dt`` in ``par[0].substeps`` sub-steps (see the module doc); returns the
    number of joints that broke.  ``V0``: scratch of at least n rows of PIVOT_COLUMNS (the sub-step's
    start velocities, which cap the bounces, and the pivots: rotation_cap.py)."""
    c = ctx[0]
    p = par[0]
    n = c.n
    h = p.h
    broken = 0
    # the passes' flags as plain booleans: numba compiles a kernel once per literal argument,
    # so solve_contacts(..., True) and (..., False) would be two kernels, and so on down the joints
    yes, no = np.bool_(True), np.bool_(False)
    if not p.warm_starting:
        zero_impulses(C, c.nc)
    prepare_contacts(c, p, B, C, R)
    gather_bodies(B, n, SB)
    if J is not None:
        if not p.warm_starting:
            zero_joint_impulses(J, c.nj)
        prepare_joints(c, B, J, JW, h, p.soft_joint[0], p.soft_joint[1], p.soft_joint[2])
        save_start(B, n, JW.X0, JW.Q0)
        save_pivots(c, B, J, JW, V0)
    eq_global = p.joint_solver == GLOBAL
    project = J is not None and eq_global and p.joint_projection
    iterations = p.iterations
    touching = c.nc > 0  # a lone or scattered body: no contact verb is called
    bouncy = False  # any restitution: the sub-step's start velocities cap the bounces
    for k in range(c.nc):
        if C.e[k] != 0.0:
            bouncy = True
            break
    fresh = no  # the joints' rows are those of the bodies' current positions (dispatch.refresh_rows)
    for _ in range(p.substeps):
        integrate_row_velocities(B, n, SB, c.gx, c.gy, h)
        if bouncy:
            save_velocities(SB, n, V0)
        if touching:
            warm_start_contacts(c, SB, C, R)
        if J is not None:
            warm_start_joints(c, B, J, JW, JS, not fresh)
        for it in range(iterations):
            if touching:
                solve_contacts(c, p, SB, C, R, yes, yes)
            if J is not None:
                solve_joints(c, B, J, JW, JS, yes, p.inv_h, eq_global)
        if S is not None and c.ns > 0:  # last before the move (module doc); on the body table
            store_velocities(B, n, SB)
            solve_springs(B, S, c.ns, h)
            load_velocities(B, n, SB)
        integrate_row_positions(B, n, SB, h, V0, np.int64(n if J is not None else 0))
        fresh = no
        if project:
            project_joints(c, B, J, JW, JS)
        if p.relax:
            if touching:
                solve_contacts(c, p, SB, C, R, no, yes)
            if J is not None:
                refresh_rows(c, B, J, JW, JS)  # the bodies moved: the rows where they are now
                solve_joints(c, B, J, JW, JS, no, p.inv_h, eq_global)
                fresh = yes  # nothing moves them before the next sub-step's warm start
        if bouncy:
            restitution_contacts(c, p, SB, C, R, V0)  # in the sub-step of first touch
    store_impulses(c, C, R)
    if J is not None:
        broken = store_joints(c, J, JW, p.inv_h)
    store_velocities(B, n, SB)
    return broken


@kernel(entry=True, runtime=True)
def soft_step_flat(ctx, par, BF, BI, CF, CI, Cpt, SF, SI, R, SB, JF, JI, JW, JS):
    """``soft_step`` over the body, contact, spring and joint tables' flat arrays (store/flat.py);
    ``JF`` None: a world without joints, ``SF`` None: one without springs (neither's code is
    compiled)."""
    B, C = bodies_view(BF, BI), contacts_view(CF, CI, Cpt)
    return soft_step(ctx, par, B, C, optional_springs(SF, SI), R, SB, optional_joints(JF, JI), JW, JS,
                     np.empty((ctx[0].n, PIVOT_COLUMNS)))
