"""The joints of the classic modes (impulse, penalty, hybrid): begin and end of a step.

Inside the step the joints are sequential-impulse rows in every sub-step of
the force integration (integrators.advance, constraints/joints/table_passes.py);
here: the rows and their warm start before the first sub-step, and after the
last one the position correction (NGS) and the readouts.  ``J`` None: a world
without joints, and these compile to nothing.
"""
from __future__ import annotations

from ..._jit import kernel
from ...constraints.body_rows import gather_all
from ...constraints.joints.dispatch import store_joints
from ...constraints.joints.position import correct_joint_positions
from ...constraints.joints.prepare import prepare_joints
from ...constraints.joints.sync import save_start


@kernel
def begin_classic_joints(c, p, B, J, JW):
    """Rows and frames for sub-steps of dt / p.substeps; step-start positions saved."""
    gather_all(B, c.n, JW.SB)
    save_start(B, c.n, JW.X0, JW.Q0)
    prepare_joints(c, B, J, JW, c.dt / p.substeps, 0.0, 1.0, 0.0)


@kernel
def end_classic_joints(c, p, B, J, JW, JS):
    """Position correction and readouts; returns the number of joints that broke (0 without joints)."""
    if J is None:
        return 0
    if p.joint_position_iterations > 0:
        correct_joint_positions(c, B, J, JW, JS, p.joint_solver == 0, 1.0, p.joint_position_iterations)
    return store_joints(c, J, JW, p.substeps / c.dt)
