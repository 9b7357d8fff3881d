"""The joint passes of modes whose contacts work on the body table (sequential_impulse, classic).

Their joints are solved on body rows like soft_step's (constraints/body_rows.py),
so each pass copies the velocities from the table into the rows and back
(sync.py); only worlds with joints pay for it.  Per step:

- ``begin_table_joints``: rows gathered, step-start positions saved, rows
  prepared rigid (these modes correct drift on the positions, not with a
  velocity bias), last step's impulses applied again (warm start);
- ``table_joint_pass``: one velocity pass (no bias) over every joint;
- ``classic_joint_substep``: the joints inside a classic mode's sub-step;
- after the positions moved: ``position.correct_joint_positions`` (NGS).
"""
from __future__ import annotations

import numpy as np

from ..body_rows import II, IM, VX, VY, W, gather_all
from .dispatch import solve_joints, warm_start_joints
from .jit import row_kernel
from .prepare import prepare_joints, zero_joint_impulses
from .sync import displacement_from_table, rows_from_table, save_start, table_from_rows


@row_kernel
def begin_table_joints(c, B, J, JW, JS, h, warm_starting):
    """Rows, frames and the warm start for a pass span ``h`` (see the module doc)."""
    n = c.n
    gather_all(B, n, JW.SB)
    save_start(B, n, JW.X0, JW.Q0)
    if not warm_starting:
        zero_joint_impulses(J, c.nj)
    prepare_joints(c, B, J, JW, h, 0.0, 1.0, 0.0)
    warm_start_joints(c, B, J, JW, JS, np.bool_(True))
    table_from_rows(B, n, JW.SB)


@row_kernel
def table_joint_pass(c, B, J, JW, JS, inv_h, eq_global):
    """One velocity pass over the joints, the table's velocities in and out."""
    rows_from_table(B, c.n, JW.SB)
    solve_joints(c, B, J, JW, JS, np.bool_(False), inv_h, eq_global)
    table_from_rows(B, c.n, JW.SB)


@row_kernel
def classic_joint_substep(c, B, J, JW, JS, h, iterations, eq_global):
    """The joints in one sub-step of a classic mode, after its integrator moved the bodies.

    The integrator moved each body by about h v; the joint rows are solved where the
    bodies were before that move (x - h v), as sequential impulses solve them at the
    step start, and the bodies then move by h v' with the velocity v' the joint passes
    left: symplectic Euler with the joint impulse, whatever integrator made v.  (Rows
    taken after the move instead made a 4 Hz wheel spring ring at 3.5 Hz.)"""
    n = c.n
    SB = JW.SB
    rows_from_table(B, n, SB)
    for i in range(n):
        if SB[i, IM] != 0.0 or SB[i, II] != 0.0:
            B.x[i, 0] -= h * SB[i, VX]
            B.x[i, 1] -= h * SB[i, VY]
            B.q[i] -= h * SB[i, W]
    displacement_from_table(B, n, JW)
    warm_start_joints(c, B, J, JW, JS, np.bool_(True))
    inv_h = 1.0 / h
    for _ in range(iterations):
        solve_joints(c, B, J, JW, JS, np.bool_(False), inv_h, eq_global)
    table_from_rows(B, n, SB)
    for i in range(n):
        if SB[i, IM] != 0.0 or SB[i, II] != 0.0:
            B.x[i, 0] += h * SB[i, VX]
            B.x[i, 1] += h * SB[i, VY]
            B.q[i] += h * SB[i, W]
