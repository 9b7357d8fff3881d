"""``impulse``: the seed's impulse-based response (6.1) with projection (3.2-3.3).

Forces are integrated first, then every point that penetrates gets the
eq. 15/16 impulse with restitution and Coulomb friction (eqs. 24-27), then
the remaining penetration is pushed out (linear or non-linear projection).
Resting contact: the impulses act like a constant contact force over the
step (position share), so a resting box is in exact equilibrium and does
not jitter.  Good for impacts and small stacks; tall stacks need many
iterations (no warm start, as in the seed).

``impulse_step`` also serves ``hybrid`` (hybrid.py), which first classifies
each point as an impact (these impulses) or resting contact (a penalty spring
inside the force integration).
"""
from __future__ import annotations

from ..._jit import kernel
from ...constraints.point import prepare_points
from ...settings import declare
from ...store.flat import bodies_view, contacts_view, springs_view
from ...store.optional import optional_joints
from .classic_joints import begin_classic_joints, end_classic_joints
from .common import (COMMON, IMPULSE_SETTINGS, NO_PENALTY, PROJECTIONS, RESTITUTION_THRESHOLD, SeedMode, auto_speed,
                     share_factor)
from .contact_geometry import classify
from .impulses import activate_impulses, position_share, save_velocities, solve_impulses
from .integrators import advance, save_start
from .penalty_load import scale_penalty_points
from .projection import project

ACTIVE_DEPTH = 1e-9  # a point takes part once it penetrates (seed: collision = overlap)


@kernel
def impulse_step(ctx, par, B, C, S, P, R, hybrid, J, JW, JS):
    """Move (forces, integrator), then resolve: impulses, position share, projection.

    With ``hybrid`` only the points ``classify`` found approaching faster than
    ``p.thr`` get impulses; the others are penalty springs during ``advance``."""
    c = ctx[0]
    p = par[0]
    n = c.n
    nc = c.nc
    save_start(B, n, R)
    prepare_points(B, C, nc, p.stick_speed, P)
    if J is not None:
        begin_classic_joints(c, p, B, J, JW)
    if hybrid:
        classify(B, C, nc, P, p.thr)
        scale_penalty_points(B, C, nc, P, p.pen[5])
    advance(c, p, B, S, C, P, R, J, JW, JS)
    save_velocities(B, n, R)
    activate_impulses(B, C, nc, P, R, ACTIVE_DEPTH, hybrid, p.thr, c.gx, c.gy, p.energy_correction,
                      p.stick_speed)
    solve_impulses(B, C, nc, P, p.iterations)
    position_share(B, n, R, p.share)
    if p.proj > 0:
        project(B, C, nc, P, R, p.allowed_penetration, p.proj == 2, p.min_linear_share,
                p.projection_iterations)
    return end_classic_joints(c, p, B, J, JW, JS)


@kernel(entry=True, runtime=True)
def impulse_step_flat(ctx, par, BF, BI, CF, CI, Cpt, SF, SI, P, R, hybrid, JF, JI, JW, JS):
    """``impulse_step`` over the body, contact, spring and joint tables' flat arrays (store/flat.py);
    ``JF`` None: a world without joints."""
    B, C, S = bodies_view(BF, BI), contacts_view(CF, CI, Cpt), springs_view(SF, SI)
    return impulse_step(ctx, par, B, C, S, P, R, hybrid, optional_joints(JF, JI), JW, JS)


class ImpulseMode(SeedMode):
    name = "impulse"
    description = ("The seed's impulse response: eq. 15 impulses with restitution and Coulomb friction "
                   "after the force integration, then linear or non-linear projection.")
    settings = declare(
        *IMPULSE_SETTINGS, RESTITUTION_THRESHOLD, *COMMON,
    )
    threshold_setting = "restitution_threshold"

    def derive(self, ctx, par, store):
        self.derive_impulses(ctx, par, NO_PENALTY, self.substeps(store, ctx, par))

    def derive_impulses(self, ctx, par, pen, substeps):
        """The derived fields of the impulse kernel for ``substeps`` and penalty parameters ``pen``."""
        v = par.values
        dt = float(ctx.get("dt"))
        integrator = self.integrator_name(ctx)
        par.set("substeps", substeps)
        par.set("thr", auto_speed(v[self.threshold_setting], float(ctx.get("gx")), float(ctx.get("gy")), dt))
        par.set("share", dt * share_factor(integrator, substeps))
        par.set("proj", PROJECTIONS.index(v["projection"]))
        par.set("pen", pen)

    def step(self, ctx, par, store):
        R, P = self.work(store.bodies.n, store.contacts.n)
        J, JW, JS = self.joints(ctx, par, store)
        JF, JI = store.joints.arrays.flat if J is not None else (None, None)
        broken = impulse_step_flat(ctx.array, par.array, *store.bodies.arrays.flat, *store.contacts.cur_cols.flat,
                                   *store.springs.arrays.flat, P, R, self.hybrid, JF, JI, JW, JS)
        self.joints_done(store, J, broken)

    hybrid = False

    def stages(self, store, values, integrator):
        out = self.force_stages(store, integrator) + ["contacts:impulse"]
        if values["projection"] != "none":
            out.append(f"projection:{values['projection']}")
        return out + self.joint_stages(store, values)
