"""``hybrid``: impulses for impacts, penalty springs for slow contact (seed 6.2.2).

At the step start every contact point is classified by its relative normal
speed: approaching faster than ``impact_speed`` is an impact (impulse with
restitution, eq. 2 correction and projection, as in ``impulse``); anything
slower is resting contact held by a penalty spring during the (sub-stepped)
force integration, as in ``penalty``.  The seed used a fixed threshold and
suggested one that adapts; the default (-1) is 3 |g| dt, three times the
speed a body gains falling for one step, so resting bodies never count as
impacts at any gravity or step size.
"""
from __future__ import annotations

from .._jit import kernel
from ..integrators import advance, save_start
from ..settings import Setting, declare
from .contact_prep import prepare_contacts, rel_velocity
from .impulse import ACTIVE_DEPTH, PROJECTIONS
from .projection import project
from .seed_contact import IMPULSE, PENALTY
from .seed_impulse import activate_impulses, position_share, save_velocities, solve_impulses
from .seed_mode import (COMMON, IMPULSE_SETTINGS, PENALTY_SETTINGS, SeedMode, auto_speed, contact_rate, penalty_params,
                        share_factor)


@kernel
def classify(B, C, nc, thr):
    """IMPULSE for points approaching faster than thr, PENALTY for the rest."""
    for k in range(nc):
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        for p in range(C.count[k]):
            dvx, dvy = rel_velocity(B, C.a[k], C.b[k], C.ra[k, p, 0], C.ra[k, p, 1], C.rb[k, p, 0],
                                    C.rb[k, p, 1])
            C.bias[k, p] = IMPULSE if dvx * nx + dvy * ny < -thr else PENALTY


@kernel
def hybrid_step(B, n, S, ns, C, nc, gx, gy, dt, R, method, substeps, iterations, thr, energy_corr,
                stick, share, proj, allow, min_linear, proj_iters, pen):
    save_start(B, n, R)
    prepare_contacts(B, C, nc, stick)
    classify(B, C, nc, thr)
    advance(method, substeps, B, n, S, ns, C, nc, gx, gy, dt, R, pen)
    save_velocities(B, n, R)
    activate_impulses(B, C, nc, R, ACTIVE_DEPTH, True, thr, gx, gy, energy_corr, stick)
    solve_impulses(B, C, nc, iterations)
    position_share(B, n, R, share)
    if proj > 0:
        project(B, C, nc, R, allow, proj == 2, min_linear, proj_iters)


class HybridMode(SeedMode):
    name = "hybrid"
    description = ("Impulses (with projection) for impacts, penalty springs for contacts slower than "
                   "an adaptive threshold (seed 6.2.2).")
    settings = declare(
        Setting("impact_speed", -1.0, -1.0, 100.0,
                "approach speed (m/s) above which a contact is an impact (impulse), below which it is "
                "resting (penalty); -1: 3 |g| dt"),
        *IMPULSE_SETTINGS, *PENALTY_SETTINGS, *COMMON,
    )

    def step(self, world, dt, p):
        n = world._bodies.n
        c = world._contacts
        g = world._gravity
        pen = penalty_params(p)
        subs = self.substeps(world, dt, p, contact_rate(pen) if c.n else 0.0)
        hybrid_step(world._bodies.view, n, world._springs.view, world._springs.n, c.cur, c.n, g[0], g[1], dt,
                    self.work(n), self.method(world), subs, p["iterations"],
                    auto_speed(p["impact_speed"], world, dt), p["energy_correction"], p["stick_speed"],
                    dt * share_factor(world.integrator, subs), PROJECTIONS[p["projection"]],
                    p["allowed_penetration"], p["min_linear_share"], p["projection_iterations"], pen)

    def stages(self, world):
        p = world._mode_settings.get(self.name) or {k: s.default for k, s in self.settings.items()}
        out = self.force_stages(world)[:-1] + ["forces:penalty_contacts (slow points)",
                                               f"integrate:{world.integrator} (sub-stepped)",
                                               "contacts:impulse (impacts)"]
        if p["projection"] != "none":
            out.append(f"projection:{p['projection']} (impacts)")
        return out
