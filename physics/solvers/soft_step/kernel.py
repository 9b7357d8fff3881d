"""The ``soft_step`` step: the constraint verbs in Box2D v3's order (solver.c, b2SolverStage).

Per step: contact rows are prepared once; then for each of N sub-steps:
integrate velocities, springs, warm start, solve contacts softly (with bias),
integrate positions, relax (solve again without bias so the push-out leaves no
velocity behind), restitution for the points that first touched in this
sub-step (constraints/contact_restitution.py; Box2D bounces once per step,
after the last sub-step, at the speed the step began with).  Finally the
impulses are stored for the next step's warm start.  Sub-stepping gives the stiffness of a small time
step at the price of one narrow phase per step (Catto, "Solver2D", 2024).
"""
from __future__ import annotations

from ..._jit import kernel
from ...constraints.body_rows import (gather_bodies, integrate_row_positions, integrate_row_velocities,
                                      load_velocities, store_velocities)
from ...constraints.contact_restitution import restitution_contacts
from ...constraints.contact_soft import prepare_contacts, solve_contacts, store_impulses, warm_start_contacts
from ...constraints.point import zero_impulses
from ...constraints.springs.substep import solve_springs


@kernel
def soft_step(ctx, par, B, C, S, R, SB):
    """One step of ``ctx[0].dt`` in ``par[0].substeps`` sub-steps (see the module doc)."""
    c = ctx[0]
    p = par[0]
    n = c.n
    h = p.h
    if not p.warm_starting:
        zero_impulses(C, c.nc)
    prepare_contacts(c, p, B, C, R)
    gather_bodies(B, n, SB)
    iterations = p.iterations
    for _ in range(p.substeps):
        integrate_row_velocities(B, n, SB, c.gx, c.gy, h)
        if c.ns > 0:  # the spring solver works on the body table
            store_velocities(B, n, SB)
            solve_springs(B, S, c.ns, h)
            load_velocities(B, n, SB)
        warm_start_contacts(c, SB, C, R)
        for it in range(iterations):
            solve_contacts(c, p, SB, C, R, True, True)
        integrate_row_positions(B, n, SB, h)
        if p.relax:
            solve_contacts(c, p, SB, C, R, False, True)
        restitution_contacts(c, p, SB, C, R)  # in the sub-step of first touch
    store_impulses(c, C, R)
    store_velocities(B, n, SB)
