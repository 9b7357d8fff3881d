"""``impulse``: the seed's impulse-based response (6.1) with projection (3.2-3.3).

Forces are integrated first, then every point that penetrates gets the
eq. 15/16 impulse with restitution and Coulomb friction (eqs. 24-27), then
the remaining penetration is pushed out (linear or non-linear projection).
Resting contact: the impulses act like a constant contact force over the
step (position share), so a resting box is in exact equilibrium and does
not jitter.  Good for impacts and small stacks; tall stacks need many
iterations (no warm start, as in the seed).
"""
from __future__ import annotations

from .._jit import kernel
from ..integrators import advance, save_start
from ..settings import Setting, declare
from .contact_prep import prepare_contacts
from .projection import project
from .seed_impulse import activate_impulses, position_share, save_velocities, solve_impulses
from .seed_mode import COMMON, IMPULSE_SETTINGS, NO_PENALTY, SeedMode, auto_speed, share_factor

ACTIVE_DEPTH = 1e-9  # a point takes part once it penetrates (seed: collision = overlap)


@kernel
def impulse_step(B, n, S, ns, C, nc, gx, gy, dt, R, method, substeps, iterations, thr, energy_corr,
                 stick, share, proj, allow, min_linear, proj_iters, pen):
    save_start(B, n, R)
    prepare_contacts(B, C, nc, stick)
    advance(method, substeps, B, n, S, ns, C, nc, gx, gy, dt, R, pen)
    save_velocities(B, n, R)
    activate_impulses(B, C, nc, R, ACTIVE_DEPTH, False, thr, gx, gy, energy_corr, stick)
    solve_impulses(B, C, nc, iterations)
    position_share(B, n, R, share)
    if proj > 0:
        project(B, C, nc, R, allow, proj == 2, min_linear, proj_iters)


PROJECTIONS = {"none": 0, "linear": 1, "nonlinear": 2}


def run_impulses(mode, world, dt, p, pen, substeps):
    c = world._contacts
    g = world._gravity
    n = world._bodies.n
    impulse_step(world._bodies.view, n, world._springs.view, world._springs.n, c.cur, c.n, g[0], g[1], dt,
                 mode.work(n), mode.method(world), substeps, p["iterations"],
                 auto_speed(p["restitution_threshold"], world, dt), p["energy_correction"], p["stick_speed"],
                 dt * share_factor(world.integrator, substeps), PROJECTIONS[p["projection"]],
                 p["allowed_penetration"], p["min_linear_share"], p["projection_iterations"], pen)


class ImpulseMode(SeedMode):
    name = "impulse"
    description = ("The seed's impulse response: eq. 15 impulses with restitution and Coulomb friction "
                   "after the force integration, then linear or non-linear projection.")
    settings = declare(
        *IMPULSE_SETTINGS,
        Setting("restitution_threshold", -1.0, -1.0, 100.0,
                "impacts slower than this (m/s) do not bounce; -1: 3 |g| dt (a resting box gains "
                "|g| dt per step and must not hop)"),
        *COMMON,
    )

    def step(self, world, dt, p):
        run_impulses(self, world, dt, p, NO_PENALTY, self.substeps(world, dt, p))

    def stages(self, world):
        p = world._mode_settings.get(self.name) or {k: s.default for k, s in self.settings.items()}
        out = self.force_stages(world) + ["contacts:impulse"]
        if p["projection"] != "none":
            out.append(f"projection:{p['projection']}")
        return out
