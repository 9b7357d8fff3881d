"""The ``soft_step`` step: the constraint verbs in Box2D v3's order (solver.c, b2SolverStage),
the contacts solved colour by colour over the wide layout (Box2D v3's constraint graph and
wide solver: constraints/colouring.py, contact_wide.py, contact_coloured.py).

Per step: the manifolds are coloured and prepared once; then for each of N sub-steps:
integrate velocities, warm start, solve contacts softly (with bias), springs, integrate
positions, relax (solve again without bias so the push-out leaves no velocity behind),
restitution for the points that first touched in this sub-step
(constraints/contact_restitution.py; Box2D bounces once per step, after the last sub-step, at
the speed the step began with).  Finally the impulses are stored for the next step's warm
start.  Sub-stepping gives the stiffness of a small time step at the price of one narrow phase
per step (Catto, "Solver2D", 2024).

Springs come last before the move, after the contacts and joints: a stiff spring is solved
implicitly (constraints/springs/substep.py) so that its stretch after the move is what it
allows, and a velocity that a later row adds along it is stored as 1/2 k (v h)^2, k h^2 / m
times that velocity's kinetic energy.  Solved first, the contacts that followed moved a 15 g
capsule on a 1.2e5 N/m spring against it (k h^2 / m = 2.7e5 at dt 0.74 s) and a step went from
1.5 J to 1360 J (tests/test_spinning_capsule_on_chain.py); solved last, it ends with 0.2 J.
A contact the spring then pushes into is pushed out again in the next sub-step, at most at
push_out_speed.

Joints (``J`` the joint table, ``JW`` their scratch, ``JS`` the global system;
physics/constraints/joints) are solved after the contacts in each pass, so the equality rows
hold exactly at the end of a sub-step when they are solved as one system (``joint_solver``
"global"); with ``joint_projection`` each sub-step's move is followed by one Newton step on the
positions of the globally solved structures, and the relax pass then makes the velocities
consistent with the projected positions (RATTLE's order, Andersen 1983).  It holds the joints
exactly (a 30-link chain whipping for 10 s: 0 mm against 3.4 mm) but removes energy: the relax
pass takes out the velocity across the projected constraint (a double pendulum lost 30 % of its
energy in 10 s; projecting once per step instead, 26 %), so it is off by default.  A world
without joints passes None for all three and the kernel is compiled without them; one without
springs passes None for ``S`` (store/optional.py).

The manifolds are prepared straight into the blocks and their impulses stored from them
(contact_prepare.prepare_wide, contact_wide.store_wide).  Restitution works on the rows ``R``
(constraints/contact_soft.py): a step with a bouncy contact prepares the rows, packs them into
the blocks, and copies what the passes accumulated back before restitution (in a sub-step where
a point may bounce; it then hands its impulses back) and before the store.
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel
from ...constraints.colouring import FLAGS, VIA_ROWS, colour_contacts
from ...constraints.body_rows import (gather_bodies, integrate_row_positions, integrate_row_velocities,
                                      load_velocities, store_velocities)
from ...constraints.contact_coloured import RELAX, SOLVE, WARM, coloured_pass
from ...constraints.contact_prepare import prepare_wide
from ...constraints.contact_restitution import restitution_contacts
from ...constraints.contact_soft import prepare_contacts, store_impulses
from ...constraints.contact_wide import bounce_due, pack, repack_normal, store_wide, unpack
from ...constraints.joints.dispatch import (project_joints, refresh_rows, solve_joints, store_joints,
                                            warm_start_joints)
from ...constraints.joints.prepare import prepare_joints, zero_joint_impulses
from ...constraints.joints.pivot import save_pivots
from ...constraints.rotation_cap import PIVOT_COLUMNS
from ...constraints.joints.sync import save_start
from ...constraints.point import zero_impulses
from ...constraints.restitution_cluster import save_velocities_of
from ...constraints.springs.substep import solve_springs
from ..joint_settings import GLOBAL


@kernel
def colour_blocks(B, C, n, nc, used, order, bstart, force, GA):
    """The manifolds coloured (colouring.colour_contacts, the colours in ``C.colour``; ``force``
    its test flags): the slots the blocks need, or minus that when ``GA`` (the blocks' body
    offsets) is shorter."""
    slots = colour_contacts(C.a, C.b, nc, B.inv_m, B.inv_i, n, used, C.colour, order, bstart, force)
    return slots if slots <= GA.shape[0] else -slots


@kernel(entry=True, runtime=True)
def soft_step_coloured(ctx, par, B, C, S, R, SB, J, JW, JS, used, order, bstart, force, W, WV, GA, GB):
    """One step (see the module doc), the contacts coloured first (colouring.colour_contacts: the
    colours in the table's ``C.colour``, kept from step to step, with the scratch ``used``,
    ``order``, ``bstart`` and the test flags ``force``; ``W``, ``WV``, ``GA``, ``GB`` the blocks'
    scratch).  Returns the number of joints that broke, or minus the slots needed when GA is too
    short (nothing changed: call again with larger blocks; sized here, the colouring costs no
    extra call from Python)."""
    c = ctx[0]
    slots = colour_blocks(B, C, c.n, c.nc, used, order, bstart, force, GA)
    if slots < 0:
        return slots
    V0 = np.empty((c.n, PIVOT_COLUMNS))
    every = np.zeros(0, np.int64)  # store/slot_list.ALL: every body
    return soft_step_wide(ctx, par, B, C, S, R, SB, J, JW, JS, V0, order, bstart, slots, W, WV, GA, GB, None,
                          every, c.n, every, c.n)


@kernel
def soft_step_wide(ctx, par, B, C, S, R, SB, J, JW, JS, V0, order, bstart, slots, W, WV, GA, GB, nthr, act, nact,
                   rows, nrows):
    """soft_step_coloured's step once the manifolds are coloured into ``slots`` slots (``order``,
    ``bstart``) and the blocks hold them: the one-call driver colours before the contact tables
    swap, so that a grow of the blocks can still call again.  ``V0``: scratch of at least n rows
    of PIVOT_COLUMNS (the sub-step's start velocities, which cap the bounces, and the pivots:
    rotation_cap.py); ``nthr`` the thread count for the split loops, None in the serial build
    (physics/threads.py).  The bodies it visits are listed (store/slot_list.py): the ``nact`` in
    ``act`` move, the ``nrows`` in ``rows`` (act's and every body a contact, joint or spring
    reaches: step/active.py) have rows in ``SB``."""
    c = ctx[0]
    p = par[0]
    n = c.n
    h = p.h
    broken = 0
    if not p.warm_starting:
        zero_impulses(C, c.nc)
    bouncy = (bstart[FLAGS] & VIA_ROWS) != 0  # (a test flag: the rows' path without restitution)
    for k in range(c.nc):
        if C.e[k] != 0.0:
            bouncy = True
            break
    gather_bodies(B, rows, nrows, SB)
    if bouncy:  # restitution works on the rows (contact_wide.py): prepare them, then the blocks
        prepare_contacts(c, p, B, C, R)
        pack(C, R, order, slots, p.block_solver, W, GA, GB)
    else:
        prepare_wide(ctx, par, B, C, order, slots, W, WV, GA, GB, nthr)
    if J is not None:
        if not p.warm_starting:
            zero_joint_impulses(J, c.nj)
        prepare_joints(c, B, J, JW, h, p.soft_joint[0], p.soft_joint[1], p.soft_joint[2])
        save_start(B, n, JW.X0, JW.Q0)
    eq_global = p.joint_solver == GLOBAL
    project = J is not None and eq_global and p.joint_projection
    if J is not None:
        save_pivots(c, B, J, JW, V0)
    # the pass kinds as plain integers: numba compiles a kernel once per literal argument
    warm, solve, relax = np.int64(WARM), np.int64(SOLVE), np.int64(RELAX)
    fresh = np.bool_(False)  # the joints' rows are those of the bodies' current positions (dispatch.refresh_rows)
    for _ in range(p.substeps):
        integrate_row_velocities(B, act, nact, SB, c.gx, c.gy, h, nthr)
        if bouncy:
            save_velocities_of(SB, rows, nrows, V0)
        coloured_pass(warm, bstart, W, WV, GA, GB, SB, p.inv_h, p.push_out_speed, p.friction_pass, nthr)
        if J is not None:
            warm_start_joints(c, B, J, JW, JS, not fresh)
        for it in range(p.iterations):
            coloured_pass(solve, bstart, W, WV, GA, GB, SB, p.inv_h, p.push_out_speed, p.friction_pass, nthr)
            if J is not None:
                solve_joints(c, B, J, JW, JS, np.bool_(True), p.inv_h, eq_global)
        if S is not None and c.ns > 0:  # last before the move (module doc; S None: no springs)
            store_velocities(B, rows, nrows, SB)
            solve_springs(B, S, c.ns, h)
            load_velocities(B, rows, nrows, SB)
        integrate_row_positions(B, act, nact, SB, h, V0, np.int64(n if J is not None else 0), nthr)
        fresh = np.bool_(False)
        if project:
            project_joints(c, B, J, JW, JS)
        if p.relax:
            coloured_pass(relax, bstart, W, WV, GA, GB, SB, p.inv_h, p.push_out_speed, p.friction_pass, nthr)
            if J is not None:
                refresh_rows(c, B, J, JW, JS)  # the bodies moved: the rows where they are now
                solve_joints(c, B, J, JW, JS, np.bool_(False), p.inv_h, eq_global)
                fresh = np.bool_(True)  # nothing moves them before the next sub-step's warm start
        if bouncy and bounce_due(W, order, slots, p.restitution_threshold):
            # restitution works on the rows: hand them over and take its impulses back
            unpack(C, W, order, slots, R)
            restitution_contacts(c, p, SB, C, R, V0)
            repack_normal(C, R, order, slots, W)
    if bouncy:
        unpack(C, W, order, slots, R)
        store_impulses(c, C, R)
    else:
        store_wide(C, W, order, slots)
    if J is not None:
        broken = store_joints(c, J, JW, p.inv_h)
    store_velocities(B, rows, nrows, SB)
    return broken
