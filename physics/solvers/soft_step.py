"""``soft_step``: the default mode — sub-stepping with soft contacts (Box2D v3 style).

Per step: contact rows are prepared once; then for each of N sub-steps:
integrate velocities, warm start, solve contacts softly (with bias), solve
springs, integrate positions, relax (solve again without bias so the
push-out leaves no velocity behind).  Finally one restitution pass.
Sub-stepping gives the stiffness of a small time step at the price of one
narrow phase per step (Catto, "Solver2D", 2024).
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from ..settings import Setting, declare
from . import SolverMode
from .contact_prep import zero_impulses
from .soft_bodies import NB, gather_bodies, integrate_positions, integrate_velocities, load_velocities, store_velocities
from .soft_contact import softness
from .soft_rows import NF, finish_rows, prepare_rows, solve_rows, warm_start_rows
from .soft_springs import solve_springs
from .warm_handoff import adopt


@kernel
def soft_step(B, n, C, nc, S, ns, gx, gy, dt, substeps, iterations, hertz, zeta, push, warm, relax,
              rest_threshold, stick_speed, block, R, SB):
    h = dt / substeps
    inv_h = 1.0 / h
    # contacts against static bodies are twice as stiff (they carry the whole load); both are
    # capped at a quarter of the sub-step rate: stiffer static rows (Box2D v3 allows 2x the cap)
    # leave a 5-box stack rocking forever at 60 Hz instead of going to sleep
    cap = 0.25 * inv_h
    soft_dyn = softness(min(hertz, cap), zeta, h)
    soft_static = softness(min(2.0 * hertz, cap), zeta, h)
    if not warm:
        zero_impulses(C, nc)
    prepare_rows(B, C, nc, stick_speed, R)
    gather_bodies(B, n, SB)
    for _ in range(substeps):
        integrate_velocities(B, n, SB, gx, gy, h)
        if ns > 0:  # the spring solver works on the body table
            store_velocities(B, n, SB)
            solve_springs(B, S, ns, h)
            load_velocities(B, n, SB)
        warm_start_rows(SB, C, nc, R)
        for it in range(iterations):
            solve_rows(SB, C, nc, R, inv_h, True, soft_dyn, soft_static, push, block, it == iterations - 1)
        integrate_positions(B, n, SB, h)
        if relax:
            solve_rows(SB, C, nc, R, inv_h, False, soft_dyn, soft_static, push, block, True)
    finish_rows(SB, C, nc, R, rest_threshold)
    store_velocities(B, n, SB)


class SoftStep(SolverMode):
    name = "soft_step"
    description = "Sub-stepped soft contacts with relax and restitution passes (Box2D v3 style); the default."
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
    )

    def __init__(self):
        self._alloc(64)

    def _alloc(self, cap):
        self.SB = np.zeros((cap, NB))
        self.R = np.zeros((64, NF))

    def step(self, world, dt, p):
        n = world._bodies.n
        if n > len(self.SB):
            self._alloc(2 * n)
        c = world._contacts
        if c.n > len(self.R):
            self.R = np.zeros((max(c.n, 2 * len(self.R)), NF))
        adopt(world, dt / p["substeps"])  # impulses per sub-step; rescaled after a mode switch
        g = world._gravity
        soft_step(world._bodies.view, n, c.cur, c.n, world._springs.view, world._springs.n,
                  g[0], g[1], dt, p["substeps"], p["iterations"], p["contact_hertz"], p["damping_ratio"],
                  p["push_out_speed"], p["warm_starting"], p["relax"], p["restitution_threshold"],
                  p["stick_speed"], p["block_solver"], self.R, self.SB)

    def stages(self, world):
        out = ["integrate:symplectic_euler (sub-stepped)", "contacts:soft"]
        if world._springs.n:
            out.append("springs:soft")
        return out
