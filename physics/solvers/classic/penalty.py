"""``penalty``: contacts as damped springs along the penetration (seed 6.2, eq. 17).

No projection and no impulses: every contact point carries a spring-damper
force (solvers/classic/penalty_force.py) that the world's integrator
integrates together with gravity and the springs, sub-stepped so that
omega h stays inside the integrator's stability range (a 25 Hz contact is
about 6 symplectic sub-steps at 60 Hz).  Good for resting contact and
stacks (smooth, no jitter); soft for fast impacts (a little overlap, bounce
set by the damping ratio that matches the restitution).
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel
from ...constraints.point import prepare_points
from ...settings import declare
from ...store.flat import bodies_view, contacts_view, springs_view
from ...store.optional import optional_joints
from .classic_joints import begin_classic_joints, end_classic_joints
from .common import COMMON, PENALTY_SETTINGS, SeedMode, contact_rate, penalty_params
from .contact_geometry import PENALTY, flag_all
from .integrators import advance, save_start
from .penalty_load import scale_penalty_points


@kernel
def penalty_step(ctx, par, B, C, S, P, R, J, JW, JS):
    c = ctx[0]
    p = par[0]
    save_start(B, c.n, R)
    prepare_points(B, C, c.nc, p.stick_speed, P)
    if J is not None:
        begin_classic_joints(c, p, B, J, JW)
    flag_all(C, c.nc, P, np.int64(PENALTY))  # not a literal: one flag_all for every role
    scale_penalty_points(B, C, c.nc, P, p.pen[5])
    advance(c, p, B, S, C, P, R, J, JW, JS)
    return end_classic_joints(c, p, B, J, JW, JS)


@kernel(entry=True, runtime=True)
def penalty_step_flat(ctx, par, BF, BI, CF, CI, Cpt, SF, SI, P, R, JF, JI, JW, JS):
    """``penalty_step`` over the body, contact, spring and joint tables' flat arrays (store/flat.py);
    ``JF`` None: a world without joints."""
    B, C, S = bodies_view(BF, BI), contacts_view(CF, CI, Cpt), springs_view(SF, SI)
    return penalty_step(ctx, par, B, C, S, P, R, optional_joints(JF, JI), JW, JS)


class PenaltyMode(SeedMode):
    name = "penalty"
    description = ("The seed's penalty contacts: damped springs along the penetration vector with a "
                   "regularised Coulomb friction force, sub-stepped automatically; no projection.")
    settings = declare(*PENALTY_SETTINGS, *COMMON)

    def derive(self, ctx, par, store):
        pen = penalty_params(par.values)
        subs = self.substeps(store, ctx, par, contact_rate(pen) if store.contacts.n else 0.0)
        par.set("pen", penalty_params(par.values, float(ctx.get("dt")), subs))
        par.set("substeps", subs)

    def step(self, ctx, par, store):
        R, P = self.work(store.bodies.n, store.contacts.n)
        J, JW, JS = self.joints(ctx, par, store)
        JF, JI = store.joints.arrays.flat if J is not None else (None, None)
        broken = penalty_step_flat(ctx.array, par.array, *store.bodies.arrays.flat, *store.contacts.cur_cols.flat,
                                   *store.springs.arrays.flat, P, R, JF, JI, JW, JS)
        self.joints_done(store, J, broken)

    def push_speed(self, values):
        # the penalty points' depth term is a velocity servo capped at push_out_speed
        # (penalty_force.normal_force; a point's cap rises to twice a remembered approach speed,
        # but that is the impact's own energy coming back, which the guard's scale covers)
        return float(values["push_out_speed"])

    def stages(self, store, values, integrator):
        return self.force_stages(store, integrator)[:-1] + ["forces:penalty_contacts",
                                                           f"integrate:{integrator} (sub-stepped)"] + \
            self.joint_stages(store, values)
