"""``hybrid``: impulses for impacts, penalty springs for slow contact (seed 6.2.2).

At the step start every contact point is classified by its relative normal
speed (contact_geometry.classify): approaching faster than ``impact_speed`` is
an impact (impulse with restitution, eq. 2 correction and projection, as in
``impulse``); anything slower is resting contact held by a penalty spring
during the (sub-stepped) force integration, as in ``penalty``.  The seed used a
fixed threshold and suggested one that adapts; the default (-1) is 3 |g| dt,
three times the speed a body gains falling for one step, so resting bodies
never count as impacts at any gravity or step size.  The kernel is
impulse.impulse_step with ``hybrid`` set.
"""
from __future__ import annotations

from ...settings import declare
from .common import COMMON, IMPACT_SPEED, IMPULSE_SETTINGS, PENALTY_SETTINGS, contact_rate, penalty_params
from .impulse import ImpulseMode


class HybridMode(ImpulseMode):
    name = "hybrid"
    description = ("Impulses (with projection) for impacts, penalty springs for contacts slower than "
                   "an adaptive threshold (seed 6.2.2).")
    settings = declare(
        IMPACT_SPEED, *IMPULSE_SETTINGS, *PENALTY_SETTINGS, *COMMON,
    )
    threshold_setting = "impact_speed"
    hybrid = True

    def derive(self, ctx, par, store):
        pen = penalty_params(par.values)
        subs = self.substeps(store, ctx, par, contact_rate(pen) if store.contacts.n else 0.0)
        self.derive_impulses(ctx, par, penalty_params(par.values, float(ctx.get("dt")), subs), subs)

    def push_speed(self, values):
        # the penalty points' depth term is a velocity servo capped at push_out_speed
        # (penalty_force.normal_force; a point's cap rises to twice a remembered approach speed,
        # but that is the impact's own energy coming back, which the guard's scale covers)
        return float(values["push_out_speed"])

    def stages(self, store, values, integrator):
        out = self.force_stages(store, integrator)[:-1] + ["forces:penalty_contacts (slow points)",
                                                           f"integrate:{integrator} (sub-stepped)",
                                                           "contacts:impulse (impacts)"]
        if values["projection"] != "none":
            out.append(f"projection:{values['projection']} (impacts)")
        return out + self.joint_stages(store, values)
