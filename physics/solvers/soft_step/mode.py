"""``soft_step``'s settings and its place in the pipeline (the step kernel is in coloured.py)."""
from __future__ import annotations

import numpy as np

from ...constraints.body_rows import NB
from ...constraints.contact_soft import FRICTION_PASSES, NF
from ...constraints.joints.work import after_step, joint_args
from ...constraints.softness import softness
from ...settings import Setting, declare
from ..base import SolverMode
from ..joint_settings import joint_solver_setting
from .fit import fit as fit_substeps
from .layout import LAYOUTS, ColouredScratch


class SoftStep(SolverMode):
    name = "soft_step"
    description = "Sub-stepped soft contacts with relax and restitution passes (Box2D v3 style); the default."
    integration = ("symplectic_euler", "symplectic Euler in sub-steps")
    settings = declare(
        Setting("substeps", 4, 1, 64, "sub-steps per step: more is stiffer and more accurate, and costs more"),
        Setting("iterations", 1, 1, 32, "biased contact passes per sub-step"),
        Setting("contact_hertz", 60.0, 1.0, 1000.0, "contact stiffness as a frequency (capped at a quarter of the sub-step rate)"),
        Setting("damping_ratio", 10.0, 0.0, 100.0, "contact damping ratio (above 1 is overdamped: no bounce from overlap)"),
        Setting("push_out_speed", 3.0, 0.0, 100.0, "largest speed (m/s) at which overlap is pushed apart"),
        Setting("warm_starting", True, doc="start from last step's impulses (matched by contact features)"),
        Setting("relax", True, doc="a pass without bias after each sub-step removes push-out velocity"),
        Setting("restitution_threshold", 1.0, 0.0, 100.0, "impacts slower than this (m/s) do not bounce"),
        Setting("stick_speed", 0.01, 0.0, 10.0, "tangential speed (m/s) below which static friction applies"),
        Setting("block_solver", True, doc="solve the two normal points of a face contact together (no rocking)"),
        Setting("friction_pass", "faces_in_relax", choices=FRICTION_PASSES,
                doc="where friction is solved: both (the biased pass and the relax pass), relax (the relax "
                    "pass only, as Box2D v3), faces_in_relax (relax only for a two-point contact between two "
                    "moving bodies, both passes for the rest: piles creep least, discs and ground contacts "
                    "settle as with both)"),
        joint_solver_setting(),
        Setting("joint_projection", False,
                doc="after each sub-step's move, one Newton step puts each globally solved structure exactly "
                    "back onto its joint constraints; exact, but it costs energy (a double pendulum loses "
                    "30 % in 10 s, against 0.4 % without)"),
        Setting("joint_hertz", 60.0, 1.0, 1000.0,
                "how fast joint drift is removed, as a frequency (capped at a quarter of the sub-step rate)"),
        # 1, not Box2D v3's 2: the stiffer drift removal leaves less drift to dissipate (a double
        # pendulum keeps its energy to 0.4 % over 10 s here, 1.6 % at 2; chains hold either way)
        Setting("joint_damping_ratio", 1.0, 0.0, 100.0, "damping ratio of the joint drift removal"),
        Setting("solver_layout", "coloured", choices=LAYOUTS, legacy=(("rows", "coloured"),),
                doc="coloured: the contacts graph-coloured (no two manifolds of a colour share a moving "
                    "body) and solved eight side by side in vector code over float32 blocks, Box2D v3's "
                    "wide solver, contacts with a fixed body last in each pass (the one layout; the "
                    "former \"rows\", one manifold at a time in table order, is read as coloured)"),
    )
    # sub-step length and its inverse; (bias rate, mass scale, impulse scale) of contacts between
    # two moving bodies and of contacts against a body that does not move
    # and the joints' (bias rate, mass scale, impulse scale) for their biased passes
    derived = (("h", np.float64), ("inv_h", np.float64), ("soft_dyn", np.float64, (3,)),
               ("soft_static", np.float64, (3,)), ("hertz_dyn", np.float64), ("hertz_static", np.float64),
               ("soft_joint", np.float64, (3,)))

    def __init__(self):
        self._alloc(64)
        self.R = np.zeros((64, NF))
        self.coloured = ColouredScratch()

    def _alloc(self, cap):
        self.SB = np.zeros((cap, NB))

    def derive(self, ctx, par, store):
        dt = ctx.get("dt")
        key = (dt, par.version)
        if getattr(par, "_derived_for", None) == key:
            return
        h = dt / par.get("substeps")
        inv_h = 1.0 / h
        hertz = par.get("contact_hertz")
        zeta = par.get("damping_ratio")
        # contacts against static bodies are twice as stiff (they carry the whole load); both are
        # capped at a quarter of the sub-step rate: stiffer static rows (Box2D v3 allows 2x the cap)
        # leave a 5-box stack rocking forever at 60 Hz instead of going to sleep
        cap = 0.25 * inv_h
        par.set("h", h)
        par.set("inv_h", inv_h)
        par.set("soft_dyn", softness(min(hertz, cap), zeta, h))
        par.set("soft_static", softness(min(2.0 * hertz, cap), zeta, h))
        # the contact rows start from these and stiffen under load (constraints/contact_stiffness.py)
        par.set("hertz_dyn", min(hertz, cap))
        par.set("hertz_static", min(2.0 * hertz, cap))
        par.set("soft_joint", softness(min(par.get("joint_hertz"), cap), par.get("joint_damping_ratio"), h))
        par._derived_for = key

    def step(self, ctx, par, store):
        n = store.bodies.n
        if n + 1 > len(self.SB):  # one more row: the world, for joints
            self._alloc(2 * n + 2)
        c = store.contacts
        if c.n > len(self.R):
            self.R = np.zeros((max(c.n, 2 * len(self.R)), NF))
        step = int(ctx.get("step"))
        c.adopt(par.get("h"), step)  # impulses per sub-step; rescaled after a switch
        J, JW, JS = joint_args(store, par.get("h"), step, self.SB)
        broken = self.coloured.step(ctx, par, store, self.R, self.SB, J, JW, JS)
        if J is not None:
            after_step(store, broken)

    def fit(self, world):
        return fit_substeps(world)  # more sub-steps for thin or small bodies (fit.py)

    def push_speed(self, values):
        # the biased rows target at most this separation speed (contact_coloured.solve_colour);
        # the relax pass then takes it out again, but with relax off it stays
        return float(values["push_out_speed"])

    def stages(self, store, values, integrator):
        out = ["integrate:symplectic_euler (sub-stepped)", "contacts:soft"]
        if store.springs.n:
            out.append("springs:soft")
        if store.joints.n:
            out.append(f"joints:soft ({values['joint_solver']})")
        return out
