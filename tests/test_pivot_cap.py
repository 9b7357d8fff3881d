"""The rotation cap of a body held by a joint keeps the joint's anchor on its path
(physics/constraints/rotation_cap.py, joints/pivot.py).

A bob on a 1.1 m rod pinned to the world, spun at 976 rad/s (14 rad per sub-step at dt 0.0588 s,
far past the cap of pi/4 per sub-step), with no gravity: a rigid pendulum keeps its energy, and a
cap may only take energy away.  Capping w alone about the centre of mass let the bob fly along at
the uncapped speed; in soft_step its energy then grew 2.5x a step (684x after 8 steps, the bob
584 m from the pivot), in sequential_impulse the joint came apart (the bob 56 m away)."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest

import physics
from physics.constraints.rotation_cap import capped

MODES = ["soft_step", "sequential_impulse"]


def kinetic(b) -> float:
    v = np.asarray(b.velocity)
    return 0.5 * b.mass * float(v @ v) + 0.5 * b.inertia * b.angular_velocity ** 2


def spun(mode, arm, w0=976.0, dt=0.0588):
    """A small triangle pinned ``arm`` m left of its centre of mass, turning about the pin."""
    w = physics.World(gravity=(0, 0), dt=dt, solver=mode, sleeping=False)
    w.energy_guard = 0  # what the solver does, not what the guard refuses
    b = w.add_body(physics.Polygon.regular(3, 0.09), position=(0, 0), angular_velocity=w0,
                   velocity=(0.0, w0 * arm), density=0.0025)
    w.add_joint("revolute", b, None, anchor=(-arm, 0.0))
    return w, b


@pytest.mark.parametrize("mode", MODES)
def test_a_pendulum_spun_past_the_cap_loses_energy_and_stays_on_its_pin(mode):
    w, b = spun(mode, arm=1.1)
    e0 = kinetic(b)
    for _ in range(8):
        w.step()
        assert kinetic(b) <= e0 * (1 + 1e-9), (kinetic(b) / e0, b.angular_velocity)
        # the chord of a pi/4 turn is 4 % shorter than its tangent step; the joint pulls the rest back
        assert abs(math.dist(b.position, (-1.1, 0.0)) - 1.1) < 0.25, b.position


@pytest.mark.parametrize("mode", MODES)
def test_a_wheel_on_its_axle_and_a_free_body_keep_their_velocity_under_the_cap(mode):
    # pinned at the centre of mass, or not pinned at all: the cap turns w down, v stays
    w, b = spun(mode, arm=0.0)
    free = w.add_body(physics.Polygon.box(0.1, 0.02), position=(5, 0), velocity=(3.0, -2.0),
                      angular_velocity=900.0)
    w.step()
    assert np.allclose(b.velocity, (0.0, 0.0), atol=1e-9) and np.allclose(b.position, (0.0, 0.0), atol=1e-9)
    assert np.allclose(free.velocity, (3.0, -2.0), rtol=1e-12)
    assert abs(b.angular_velocity) < 976.0 and abs(free.angular_velocity) < 900.0


def test_the_cap_about_an_anchor_never_adds_kinetic_energy():
    # the helper is compiled into the steps only (no Python entry): its Python source is the same rule
    rnd = random.Random(7)
    for _ in range(2000):
        vx, vy = rnd.uniform(-50, 50), rnd.uniform(-50, 50)
        w = rnd.choice([-1, 1]) * 10 ** rnd.uniform(2, 4)
        im, ii = 10 ** rnd.uniform(-3, 3), 10 ** rnd.uniform(-3, 5)
        rx, ry = rnd.uniform(-2, 2), rnd.uniform(-2, 2)
        ux, uy, wc, changed = capped.py_func(vx, vy, w, im, ii, rx, ry, 1 / 240)
        ke0 = 0.5 * (vx * vx + vy * vy) / im + 0.5 * w * w / ii
        ke1 = 0.5 * (ux * ux + uy * uy) / im + 0.5 * wc * wc / ii
        assert ke1 <= ke0 * (1 + 1e-12)
        if changed:  # the anchor's velocity is kept: v + w x r before and after
            assert math.isclose(vx - w * ry, ux - wc * ry, rel_tol=1e-9, abs_tol=1e-9 * abs(w))
            assert math.isclose(vy + w * rx, uy + wc * rx, rel_tol=1e-9, abs_tol=1e-9 * abs(w))
