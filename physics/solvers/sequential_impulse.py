"""``sequential_impulse``: projected Gauss-Seidel on accumulated impulses.

The classic rigid-contact solver of Box2D 2.x and Chipmunk (Catto, "Iterative
Dynamics with Temporal Coherence", GDC 2005; "Fast and Simple Physics using
Sequential Impulses", GDC 2006).  One step:

1. contact rows (anchors, effective masses, pre-step normal speed, mu);
2. velocities += dt * (gravity + F/m); springs (one impulse, implicit when stiff);
3. warm start: re-apply last step's accumulated impulses (matched by feature
   ids in the narrow phase) -- what makes a tall stack converge in 8 sweeps;
4. ``velocity_iterations`` PGS sweeps: friction clamped to mu * j_n, normal
   impulses clamped >= 0, speculative points may only close their gap;
5. positions += dt * velocities;
6. restitution pass for impacts faster than ``restitution_threshold``
   (v_n' = -e v_n0, after the move as Box2D v3 does, so a speculative hit
   bounces at the surface, not a gap before it);
7. position correction: ``split_impulse`` (pseudo-velocities, ``position_iterations``
   sweeps, no momentum left behind; the default) or ``baumgarte`` (a velocity bias
   in step 4, cheaper, adds some bounce to deep overlaps).
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from ..settings import Setting, declare
from . import SolverMode
from .contact_prep import prepare_contacts, zero_impulses
from .motion import integrate_positions, integrate_velocities, reset_displacements
from .si_contact import contact_bias, solve_velocities
from .soft_contact import apply_restitution, warm_start
from .soft_springs import solve_springs
from .warm_handoff import adopt
from .split_impulse import integrate_pseudo, reset_pseudo, solve_split, zero_rows

BAUMGARTE, SPLIT = 0, 1
CORRECTIONS = {"baumgarte": BAUMGARTE, "split_impulse": SPLIT}
# largest push-out speed of the position correction (m/s); Box2D 2.x caps the
# correction at 0.2 m per step, i.e. 12 m/s at 60 Hz
MAX_PUSH = 10.0


@kernel
def si_step(B, n, C, nc, S, ns, gx, gy, dt, vel_iters, pos_iters, warm, beta, slop, correction,
            rest_threshold, stick_speed, block, DP, DQ, DC, DS, VP, WP, JP):
    inv_dt = 1.0 / dt
    prepare_contacts(B, C, nc, stick_speed)
    if not warm:
        zero_impulses(C, nc)
    integrate_velocities(B, n, gx, gy, dt)
    if ns > 0:
        solve_springs(B, S, ns, dt)
    contact_bias(C, nc, inv_dt, beta, slop, MAX_PUSH, correction == BAUMGARTE)
    warm_start(B, C, nc)
    for _ in range(vel_iters):
        solve_velocities(B, C, nc, block)
    reset_displacements(n, DP, DQ, DC, DS)
    integrate_positions(B, n, dt, DP, DQ, DC, DS)
    # after the move, so a speculative hit bounces at the wall rather than a gap away from it
    apply_restitution(B, C, nc, rest_threshold, C.jn)
    if correction == SPLIT and pos_iters > 0:
        reset_pseudo(n, VP, WP)
        zero_rows(JP, nc)
        for _ in range(pos_iters):
            solve_split(B, C, nc, VP, WP, JP, inv_dt, beta, slop, MAX_PUSH)
        integrate_pseudo(B, n, dt, VP, WP)


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
                choices=tuple(CORRECTIONS)),
        Setting("restitution_threshold", 1.0, 0.0, 100.0, "impacts slower than this (m/s) do not bounce"),
        Setting("stick_speed", 0.01, 0.0, 10.0, "tangential speed (m/s) below which static friction applies"),
        Setting("block_solver", False, doc="solve the two normal points of a face contact together (Box2D 2.x block solver; off: it converges faster per face but stacks drift more here)"),
    )

    def __init__(self):
        self._alloc_bodies(64)
        self.JP = np.zeros((256, 2))

    def _alloc_bodies(self, cap):
        self.DP = np.zeros((cap, 2))
        self.DQ = np.zeros(cap)
        self.DC = np.ones(cap)
        self.DS = np.zeros(cap)
        self.VP = np.zeros((cap, 2))
        self.WP = np.zeros(cap)

    def step(self, world, dt, p):
        n = world._bodies.n
        if n > len(self.DQ):
            self._alloc_bodies(2 * n)
        c = world._contacts
        if c.n > len(self.JP):
            self.JP = np.zeros((2 * c.n, 2))
        adopt(world, dt)
        g = world._gravity
        si_step(world._bodies.view, n, c.cur, c.n, world._springs.view, world._springs.n,
                g[0], g[1], dt, p["velocity_iterations"], p["position_iterations"], p["warm_starting"],
                p["baumgarte"], p["linear_slop"], CORRECTIONS[p["position_correction"]],
                p["restitution_threshold"], p["stick_speed"], p["block_solver"],
                self.DP, self.DQ, self.DC, self.DS, self.VP, self.WP, self.JP)

    def stages(self, world):
        out = ["integrate:symplectic_euler", "contacts:sequential_impulse",
               f"position_correction:{world.settings_for(self.name)['position_correction']}"]
        if world._springs.n:
            out.append("springs")
        return out
