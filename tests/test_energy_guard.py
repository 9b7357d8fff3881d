"""The energy guard (issue 20): a step that gains energy it cannot have been given is refused.

Bound (physics/step/energy_guard.py): from the reference state, E <= E0 + r (S0 + S/2) + the
push-out allowance + the noise floor, r = world.energy_guard = 1.  These tests check that honest motion stays
inside (free fall: symplectic Euler's analytic gain m g^2 h^2 / 2 per step), that a real
energy gain is refused, and that external input (user forces, moving kinematic bodies,
motors) and edits between steps are not mistaken for one.
"""
import math

import pytest

import physics
from physics.errors import SimulationError
from physics.step.energy_guard import energies, noise_floor

MODES = physics.solvers_available()


@pytest.mark.parametrize("mode", MODES)
def test_free_fall_from_rest_is_not_refused(mode):
    """A box falling from rest at the origin (E0 = S0 = 0): symplectic Euler gains exactly
    m g^2 h^2 / 2 per step (v_n = n g h, x_n = -g h^2 n (n + 1) / 2), inside S/2 from the
    first step on; 300 steps run."""
    w = physics.World(solver=mode)
    b = w.add_body(physics.Polygon.box(1, 1))
    for _ in range(300):
        w.step()
    h, g, n = w.dt, 9.81, 300
    e, _ = energies(w)
    assert e <= 0.5 * b.mass * g * g * h * h * n * (1 + 1e-9) + 1e-9
    assert w.fault is None


@pytest.mark.parametrize("mode", MODES)
def test_a_resting_stack_is_not_refused(mode):
    w = physics.World(solver=mode)
    w.add_body(physics.Polygon.box(40, 1), kind="static", position=(0, -0.5))
    for i in range(5):
        w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5 + 1.01 * i))
    for _ in range(240):
        w.step()
    assert w.fault is None


def exploding_spring(guard=1.0):
    """Explicit Euler on an undamped spring gains (1 + (omega h)^2) per sub-step (the seed
    modes allow omega h <= 0.2 with it: 4 % per sub-step): a real, unbounded energy gain."""
    w = physics.World(solver="impulse", gravity=(0, 0), integrator="euler")
    w.energy_guard = guard
    b = w.add_body(physics.Circle(0.1), position=(1.0, 0.0))
    w.add_spring(b, None, anchor_b=(0.0, 0.0), stiffness=100.0, rest_length=0.0)
    return w, b


def test_an_explicit_euler_explosion_is_refused_with_the_state_kept():
    w, b = exploding_spring()
    e0, s0 = energies(w)
    with pytest.raises(SimulationError, match="total energy") as info:
        for _ in range(2000):
            before = (b.position, b.velocity)
            w.step()
            e, s = energies(w)
            assert e <= e0 + s0 + 0.5 * s + noise_floor(w, w.dt) + 1e-9  # every accepted step inside the bound
    assert info.value.stage == "solve" and w.fault is info.value
    assert (b.position, b.velocity) == before  # reverted to the step's start
    e, s = energies(w)
    assert e > 2.0 * e0  # it did gain (E = S here: caught once S > 4 E0)


def test_the_guard_can_be_turned_off_and_is_validated():
    w, _ = exploding_spring(guard=0.0)
    for _ in range(300):
        w.step()
    assert energies(w)[0] > 1e3 * 0.5 * 100.0  # the explosion ran
    for bad in (-1.0, math.nan, math.inf, "1"):
        with pytest.raises(ValueError, match="energy_guard"):
            w.energy_guard = bad


def test_user_forces_are_external_input():
    """A constant push on a free body raises its energy as F^2 t^2 / 2m: never refused."""
    w = physics.World(gravity=(0, 0))
    b = w.add_body(physics.Circle(0.5))
    for _ in range(300):
        b.apply_force((50.0, 0.0))
        w.step()
    assert b.velocity[0] == pytest.approx(50.0 / b.mass * 300 * w.dt, rel=1e-9)


def test_a_moving_kinematic_body_is_external_input():
    """A kinematic paddle at 20 m/s sweeps resting boxes along: their energy comes from it."""
    w = physics.World(solver="soft_step")
    w.add_body(physics.Polygon.box(200, 1), kind="static", position=(0, -0.5))
    w.add_body(physics.Polygon.box(0.5, 2), kind="kinematic", position=(-2, 1), velocity=(20.0, 0.0))
    boxes = [w.add_body(physics.Polygon.box(1, 1), position=(1.0 + 1.2 * i, 0.5)) for i in range(3)]
    for _ in range(60):
        w.step()
    assert w.fault is None and max(b.velocity[0] for b in boxes) > 10.0


def test_a_motor_is_external_input():
    """A revolute motor spins a wheel up to 50 rad/s from rest."""
    w = physics.World(gravity=(0, 0))
    wheel = w.add_body(physics.Circle(0.5))
    w.add_joint("revolute", wheel, None, anchor=(0, 0), motor_speed=50.0, max_motor_torque=100.0)
    for _ in range(120):
        w.step()
    assert wheel.angular_velocity == pytest.approx(50.0, rel=1e-3)


def test_an_edit_between_steps_starts_a_new_reference():
    """Setting a velocity 100 times the old one is an edit, not a gain of the step."""
    w = physics.World(gravity=(0, 0))
    b = w.add_body(physics.Circle(0.5))
    b.velocity = (0.1, 0.0)
    w.step()
    b.velocity = (10.0, 0.0)
    for _ in range(10):
        w.step()
    assert w.fault is None and b.velocity[0] == pytest.approx(10.0)


def test_a_welded_cantilever_at_rest_near_zero_energy_is_not_refused():
    """E0 = S0 = 0 (a horizontal bar at y = 0, at rest): the solver's 1e-32 J of noise is not a
    gain (the noise floor); 120 steps run in the joint modes."""
    for mode in ("soft_step", "sequential_impulse"):
        w = physics.World(solver=mode)
        links = [w.add_body(physics.Polygon.box(1.0, 0.2), position=(0.5 + i, 0.0)) for i in range(4)]
        w.add_joint("weld", links[0], None, anchor=(0.0, 0.0))
        for a, b in zip(links, links[1:]):
            w.add_joint("weld", a, b, anchor=(b.position[0] - 0.5, 0.0))
        for _ in range(120):
            w.step()
        assert w.fault is None
