"""The energy guard's scale counts heights from the reference's lowest body, not the step's.

Its bound is E0 + r (S0 + S / 2) + ..., with S's gravitational part the height the bodies can
still fall, sum_i m_i |g| (h_i - h_min) (physics/step/energy_guard.py).  Measured from the step's
own lowest body, a light body thrown far down raised every other body's m g h: the world fuzzer
(seed 1, case 16150) spun a 6.5 ug disc to 7e7 rad/s in one soft_step step while a 0.2 ug box fell
9,000 km, and the 141 kg body beside them lent the bound 1.3e10 J, so a step from 2.7e4 J to
3.9e9 J was accepted (141,700 times the starting scale, by the fuzzer's own energy measure).
"""
from __future__ import annotations

import random

import numpy as np

from bench.fuzz.check import run_case
from bench.fuzz.energy import EnergyBound
from bench.fuzz.worlds import build
from physics.errors import SimulationError
from physics.step.energy_bound import (
    ACTIVE,
    SLOTS,
    energy_and_scale,
    guard_begin,
    guard_excess,
)
from physics.step.energy_sums import KE, LOWEST, MASS, PE, SUMS

G_ = 9.81


def sums(bodies, ke):
    """A sums array for bodies given as (mass, height) pairs at rest plus ``ke`` J of motion."""
    s = np.zeros(SUMS)
    phi = np.array([G_ * h for _, h in bodies])           # potential per kg
    m = np.array([m for m, _ in bodies])
    s[KE], s[PE], s[MASS], s[LOWEST] = ke, float((m * phi).sum()), float(m.sum()), float(phi.min())
    return s


def test_a_light_body_thrown_down_lends_the_bound_nothing():
    heavy, light = (141.0, 1.2), (2e-7, 1.1)
    start = sums([heavy, light], ke=0.0)
    # a step that gives 1e6 J of motion (no cause: no input, no overlap) and throws the light body
    # 9,000 km down: 0.02 J of its own potential
    end = sums([heavy, (light[0], -9.0e6)], ke=1.0e6)
    G = np.zeros(SLOTS)
    G[0] = np.nan          # LAST: no step before
    guard_begin(G, start, 1.0, 0.0, False)
    assert G[ACTIVE] == 1.0
    assert guard_excess(G, end, 1.0, 1 / 60, G_, 0.005, 0.0)
    # measured from the step's lowest body, the heavy body's 141 kg x 9,000 km would cover it
    e, s_step = energy_and_scale(end)
    assert e < 0.5 * s_step


def test_an_honest_fall_keeps_its_slack():
    """A body falls from rest (S0 = 0), below where it started, so below the reference's lowest
    body: S keeps its kinetic energy, and an integrator's gain on a fall, m g^2 dt^2 / 2 a step
    (energy_guard.py: the S / 2 term is for this), stays inside the bound."""
    start = sums([(1.0, 3.0)], ke=0.0)
    dt, n = 1 / 60, 38
    drop = G_ * dt * dt * n * (n + 1) / 2            # n steps of symplectic Euler from rest
    ke = G_ * G_ * dt * dt * (n * (n + 1) / 2 + n / 2)  # the potential lost, plus the gain
    end = sums([(1.0, 3.0 - drop)], ke=ke)
    G = np.zeros(SLOTS)
    G[0] = np.nan
    guard_begin(G, start, 1.0, 0.0, False)
    assert not guard_excess(G, end, 1.0, dt, G_, 0.005, 0.0)
    # the gain (0.5 J) is beyond the noise floor alone: the slack that holds it is S / 2
    assert 0.5 * G_ * G_ * dt * dt * n > 1.0 * (G_ * 0.005 + 0.5 * (G_ * dt) ** 2 + 0.5e-6)


def test_the_fuzzers_case_is_refused_not_accepted():
    r = run_case(16150, base=1)
    assert r["mode"] == "soft_step"
    # every accepted step stayed near its starting energy (the fuzzer's own measure), and the
    # step that spun the disc up was refused and reverted
    assert r["gain"] < 1.0, r
    assert r["outcome"] == "refused" and r["reason"] == "energy_guard", r


def test_the_fuzzers_measure_counts_heights_from_the_start():
    plan = build(random.Random("world:1:16150"))
    w = plan.world
    bound = EnergyBound(w)
    low0 = bound.energy.low0
    try:
        w.step()
    except SimulationError:
        pass
    bound.energy(w)
    assert bound.energy.low0 == low0
