"""``penalty``: contacts as damped springs along the penetration (seed 6.2, eq. 17).

No projection and no impulses: every contact point carries a spring-damper
force (physics/solvers/penalty_force.py) that the world's integrator
integrates together with gravity and the springs, sub-stepped so that
omega h stays inside the integrator's stability range (a 25 Hz contact is
about 6 symplectic sub-steps at 60 Hz).  Good for resting contact and
stacks (smooth, no jitter); soft for fast impacts (a little overlap, bounce
set by the damping ratio that matches the restitution).
"""
from __future__ import annotations

from .._jit import kernel
from ..integrators import advance, save_start
from ..settings import declare
from .contact_prep import prepare_contacts
from .seed_contact import PENALTY
from .seed_mode import COMMON, PENALTY_SETTINGS, SeedMode, penalty_params, contact_rate


@kernel
def flag_all(C, nc, value):
    for k in range(nc):
        for p in range(C.count[k]):
            C.bias[k, p] = value


@kernel
def penalty_step(B, n, S, ns, C, nc, gx, gy, dt, R, method, substeps, stick, pen):
    save_start(B, n, R)
    prepare_contacts(B, C, nc, stick)
    flag_all(C, nc, PENALTY)
    advance(method, substeps, B, n, S, ns, C, nc, gx, gy, dt, R, pen)


class PenaltyMode(SeedMode):
    name = "penalty"
    description = ("The seed's penalty contacts: damped springs along the penetration vector with a "
                   "regularised Coulomb friction force, sub-stepped automatically; no projection.")
    settings = declare(*PENALTY_SETTINGS, *COMMON)

    def step(self, world, dt, p):
        n = world._bodies.n
        c = world._contacts
        g = world._gravity
        pen = penalty_params(p)
        subs = self.substeps(world, dt, p, contact_rate(pen) if c.n else 0.0)
        penalty_step(world._bodies.view, n, world._springs.view, world._springs.n, c.cur, c.n, g[0], g[1],
                     dt, self.work(n), self.method(world), subs, p["stick_speed"], pen)

    def stages(self, world):
        return self.force_stages(world)[:-1] + ["forces:penalty_contacts",
                                                 f"integrate:{world.integrator} (sub-stepped)"]
