"""``sequential_impulse``'s settings and its place in the pipeline (the kernel is in kernel.py)."""
from __future__ import annotations

from collections import namedtuple

import numpy as np

from ...constraints.joints.work import after_step, joint_args
from ...constraints.point import point_rows, point_type
from ...constraints.rotation_cap import PIVOT_COLUMNS
from ...settings import Setting, declare
from ..base import SolverMode
from ..joint_settings import GLOBAL as _GLOBAL
from ..joint_settings import joint_position_setting, joint_solver_setting
from .kernel import BAUMGARTE, GLOBAL, MAX_PUSH, SPLIT, si_step_flat

assert GLOBAL == _GLOBAL

CORRECTIONS = ("baumgarte", "split_impulse")
assert CORRECTIONS.index("baumgarte") == BAUMGARTE and CORRECTIONS.index("split_impulse") == SPLIT

# displacements since the step began (DP, DQ and its cos/sin DC, DS) and the pseudo-velocities
# of the split impulses (VP, WP), the rotation cap's pivots (PV: constraints/rotation_cap.py)
Motion = namedtuple("Motion", "DP DQ DC DS VP WP PV")
# per point: the velocity bias and the split impulses' accumulated pseudo impulse
SIPoints = point_type("SIPoints", __name__, extra=(("bias", np.float64), ("jp", np.float64)))


class SequentialImpulse(SolverMode):
    name = "sequential_impulse"
    description = "Rigid contacts by projected Gauss-Seidel on accumulated impulses with warm starting " \
                  "(Box2D 2.x / Chipmunk style)."
    settings = declare(
        Setting("velocity_iterations", 8, 1, 256, "Gauss-Seidel sweeps over the contact velocity rows per step"),
        Setting("position_iterations", 3, 0, 256, "sweeps over the position rows (split impulses) per step"),
        Setting("warm_starting", True, doc="start from last step's impulses (matched by contact features)"),
        Setting("baumgarte", 0.2, 0.0, 1.0, "fraction of the overlap beyond the slop removed per step"),
        Setting("linear_slop", 0.005, 0.0, 1.0, "overlap (m) left uncorrected so resting contacts persist"),
        Setting("position_correction", "split_impulse",
                doc="split_impulse: pseudo-velocities that move positions but leave no momentum; "
                    "baumgarte: a velocity bias (cheaper, springier)",
                choices=CORRECTIONS),
        Setting("restitution_threshold", 1.0, 0.0, 100.0, "impacts slower than this (m/s) do not bounce"),
        Setting("stick_speed", 0.01, 0.0, 10.0, "tangential speed (m/s) below which static friction applies"),
        Setting("block_solver", False, doc="solve the two normal points of a face contact together (Box2D 2.x block solver; off: it converges faster per face but stacks drift more here)"),
        joint_solver_setting(),
        joint_position_setting(),
    )
    derived = (("inv_dt", np.float64),)

    def __init__(self):
        self._alloc_bodies(64)
        self._alloc_rows(256)

    def _alloc_bodies(self, cap):
        self.M = Motion(np.zeros((cap, 2)), np.zeros(cap), np.ones(cap), np.zeros(cap),
                        np.zeros((cap, 2)), np.zeros(cap), np.zeros((cap, PIVOT_COLUMNS)))

    def _alloc_rows(self, cap):
        self.W = point_rows(SIPoints, cap)

    def derive(self, ctx, par, store):
        par.set("inv_dt", 1.0 / ctx.get("dt"))

    def step(self, ctx, par, store):
        n = store.bodies.n
        if n > len(self.M.DQ):
            self._alloc_bodies(2 * n)
        c = store.contacts
        if c.n > len(self.W.bias):
            self._alloc_rows(2 * c.n)
        step = int(ctx.get("step"))
        c.adopt(ctx.get("dt"), step)
        J, JW, JS = joint_args(store, ctx.get("dt"), step)
        JF, JI = store.joints.arrays.flat if J is not None else (None, None)
        broken = si_step_flat(ctx.array, par.array, *store.bodies.arrays.flat, *c.cur_cols.flat,
                              *store.springs.arrays.flat, self.W, self.M, JF, JI, JW, JS)
        if J is not None:
            after_step(store, broken)

    def push_speed(self, values):
        # split impulses move positions with pseudo-velocities that are dropped after the move;
        # Baumgarte's bias is a real velocity, capped at MAX_PUSH (contact_rigid.contact_bias)
        return MAX_PUSH if values["position_correction"] == "baumgarte" else 0.0

    def stages(self, store, values, integrator):
        out = ["integrate:symplectic_euler", "contacts:sequential_impulse",
               f"position_correction:{values['position_correction']}"]
        if store.springs.n:
            out.append("springs")
        if store.joints.n:
            out.append(f"joints:sequential_impulse ({values['joint_solver']}, ngs)")
        return out
