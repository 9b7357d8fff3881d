"""A lone body on an undamped spring gains no energy in a step, however large the step.

The bound: with no damping, no contact, no joint and no input, the energy of the world, kinetic +
elastic + gravity measured from the start (bench/fuzz/energy.py, computed outside the engine),
is conserved by the motion; backward Euler on the spring (the implicit springs of soft_step and
sequential_impulse, constraints/springs/substep.py) may only remove it.  So no step may end with
more than it started with.  The tolerance is 1 % of the world's energy scale (the aim of the
reliability fuzzer, docs/reliability.md): S0 (kinetic + elastic at the start) plus m |g| L, the
energy of a fall through the spring's own length (a body released at rest has S0 = 0).

Two solver gains broke it:

- the rotation cap (constraints/rotation_cap.py MAX_ROTATION, pi/4 per sub-step) was applied when
  positions were integrated, after the springs were solved: the implicit spring set the angular
  velocity that removes its stretch through the anchor's arm, the cap then clamped it, and the
  linear half of the spring's impulse moved the anchor alone.  A 15 g capsule on a 1.2e5 N/m
  spring (soft_step, dt 0.74 s: the second step of tests/test_spinning_capsule_on_chain.py,
  taken off the ground) went from 0.021 J to 985 J in one step.
- the springs were solved linearised at the (sub-)step's start: the axis and the arms frozen.
  At a large step a body moves far across the axis (sequential_impulse solves its springs once
  per step, h = dt): a 15 g box released at rest on a 1e4 N/m spring at dt 0.2 s moved 0.3 m
  across a 0.58 m spring in its first step, and the spring stored the stretch that made (1e3 x
  the scale in 20 steps, 2e7 x at dt 0.74 s).
"""
import math

import pytest

import physics

from bench.fuzz.energy import Energy

G = 9.81
ANCHOR = (0.3, 0.5)


def lone(solver, dt, k, m, spin=0.0, anchor=(0.0, 0.0), velocity=(0.0, 0.0), capsule=False):
    w = physics.World(solver=solver, dt=dt)
    w.energy_guard = 0.0  # the solver's own energy, not the guard's refusal
    shape = (physics.Capsule((-0.06153, 0.0), (0.06153, 0.0), 0.05046) if capsule
             else physics.Polygon.box(0.2, 0.1))
    b = w.add_body(shape, velocity=velocity, angular_velocity=spin)
    b.density = b.density * m / b.mass
    s = w.add_spring(b, None, anchor_a=anchor, anchor_b=ANCHOR, stiffness=k)
    return w, b, s


def capsule_off_the_ground(solver):
    """The capsule of tests/test_spinning_capsule_on_chain.py as soft_step left it after its first
    step (above the chain, out of reach of it): what the spring alone does from there."""
    w = physics.World(solver=solver, dt=0.74)
    w.energy_guard = 0.0
    cap = physics.Capsule((-0.06153, 0.0), (0.06153, 0.0), 0.05046)
    b = w.add_body(cap, position=(0.3780660749387653, 1.365938484664665), angle=1.6001634915037117,
                   velocity=(0.0946066159205004, -0.24169882728539122), angular_velocity=-1.034257526490049)
    b.density = b.density * 0.015 / b.mass
    s = w.add_spring(b, None, anchor_a=(0.0179, 0.04498), anchor_b=(0.70719, 0.67816), stiffness=1.2e5,
                     rest_length=0.7983509383110236)
    return w, b, s


def largest_gain(w, b, s, steps):
    """max over the steps of (E - E_before_the_step) / scale, and of (E - E0) / scale."""
    energy = Energy(w)
    e0, s0 = energy(w)
    scale = s0 + b.mass * G * s.rest_length
    step_gain = run_gain = 0.0
    e_prev = e0
    for _ in range(steps):
        w.step()
        e, _ = energy(w)
        assert math.isfinite(e)
        step_gain = max(step_gain, (e - e_prev) / scale)
        run_gain = max(run_gain, (e - e0) / scale)
        e_prev = e
    return step_gain, run_gain


@pytest.mark.parametrize("solver", ["soft_step", "sequential_impulse"])
def test_a_capsule_held_at_the_rotation_cap_gains_nothing_from_its_spring(solver):
    """The 985 J step: the capsule turns at the cap while its stiff spring pulls on a 6 cm arm."""
    w, b, s = capsule_off_the_ground(solver)
    step_gain, run_gain = largest_gain(w, b, s, 5)
    assert step_gain <= 0.01 and run_gain <= 0.01, (step_gain, run_gain)


# (dt, k, m, spin, anchor, velocity): sequential_impulse's step is one spring solve (h = dt);
# soft_step's four sub-steps at dt 0.74 are h = 0.185
CASES = [
    (0.2, 1e2, 0.015, 0.0, (0.0, 0.0), (0.0, 0.0)),
    (0.2, 1e4, 0.015, 0.0, (0.0, 0.0), (0.0, 0.0)),
    (0.2, 1e4, 1.0, 0.0, (0.018, 0.045), (3.0, -1.0)),
    (0.05, 1.2e5, 0.015, 0.0, (0.018, 0.045), (3.0, -1.0)),
    (0.74, 1e2, 1.0, 0.0, (0.0, 0.0), (0.0, 0.0)),
    (0.74, 1.2e5, 0.015, 0.0, (0.018, 0.045), (0.0, 0.0)),
    (0.2, 1.2e5, 0.015, 218.0, (0.018, 0.045), (0.0, 0.0)),
    (0.74, 1.2e5, 0.015, 218.0, (0.018, 0.045), (3.0, -1.0)),
]


@pytest.mark.parametrize("solver", ["sequential_impulse", "soft_step"])
@pytest.mark.parametrize("dt, k, m, spin, anchor, velocity", CASES)
def test_a_lone_body_on_a_stiff_spring_gains_nothing_at_large_steps(solver, dt, k, m, spin, anchor, velocity):
    w, b, s = lone(solver, dt, k, m, spin, anchor, velocity, capsule=spin != 0.0)
    step_gain, run_gain = largest_gain(w, b, s, 20)
    assert step_gain <= 0.01 and run_gain <= 0.01, (step_gain, run_gain)
