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


def test_a_motor_may_add_the_work_it_does():
    """A revolute motor spins a wheel up to 50 rad/s from rest: 1/2 I w^2 = 123 J, all of it the
    motor's work (at most T |w| per second), under a guard that stays on."""
    w = physics.World(gravity=(0, 0))
    wheel = w.add_body(physics.Circle(0.5))
    w.add_joint("revolute", wheel, None, anchor=(0, 0), motor_speed=50.0, max_motor_torque=100.0)
    for _ in range(120):
        w.step()
        assert w._pipeline._guard.active
    assert wheel.angular_velocity == pytest.approx(50.0, rel=1e-3)


def _spring_beside_a_motor(**motor):
    """The exploding spring of ``exploding_spring``, and away from it a wheel on a revolute joint
    to the world (``motor``: the joint's motor parameters)."""
    w, _ = exploding_spring()
    wheel = w.add_body(physics.Circle(0.5), position=(10.0, 0.0))
    w.add_joint("revolute", wheel, None, anchor=(10.0, 0.0), **motor)
    return w


@pytest.mark.parametrize("motor", [dict(motor_speed=0.0, max_motor_torque=0.05),
                                   dict(motor_speed=2.0, max_motor_torque=0.05)], ids=["friction", "driven"])
def test_a_motor_does_not_switch_the_guard_off(motor):
    """Joint friction (a motor of speed 0 and a small torque, the ragdoll's recipe) and a small
    driven motor leave the guard on: the explicit Euler explosion beside them is refused.  (When
    any working motor switched the guard off, the whole world ran unguarded.)"""
    w = _spring_beside_a_motor(**motor)
    with pytest.raises(SimulationError, match="total energy"):
        for _ in range(3000):
            w.step()


def test_a_mouse_drag_is_the_users_input():
    """The mouse joint pulls with the user's hand: no bound on the energy it puts in."""
    w = physics.World(gravity=(0, 0))
    w.sleeping = False
    b = w.add_body(physics.Circle(0.5))
    mouse = w.add_joint("mouse", b, None, target=(0.0, 0.0), max_force=1e4)  # grabbed at its centre,
    mouse.target = (50.0, 0.0)                                                  # then pulled
    for _ in range(60):
        w.step()
        assert not w._pipeline._guard.active
    assert b.position[0] > 40.0  # pulled most of the 50 m


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


def _refusal_step(height: float, steps: int = 4000):
    """The step at which the exploding spring of ``exploding_spring``, hung in gravity with its
    anchor ``height`` m up, is refused (None: never)."""
    w = physics.World(solver="impulse", gravity=(0, -10), integrator="euler")
    b = w.add_body(physics.Circle(0.1), position=(1.0, height))
    w.add_spring(b, None, anchor_b=(0.0, height), stiffness=100.0, rest_length=0.0)
    for i in range(steps):
        try:
            w.step()
        except SimulationError:
            return i
    return None


def test_the_bound_does_not_depend_on_where_the_origin_is():
    """The same exploding world at the origin and 100 km up (gravity on) is refused at the same
    step, give or take rounding: the scale measures gravitational energy from the reference
    state, so m g y of a far-off origin buys no slack (with |m g y| in the scale, the world 100 km
    up ran 31 kJ of slack and went unrefused)."""
    here, up = _refusal_step(0.0), _refusal_step(1e5)
    assert here is not None and up is not None
    assert abs(here - up) <= 2, (here, up)


@pytest.mark.parametrize("height", [0.0, 1e5])
def test_the_numpy_reference_is_the_guards_own_measure(height):
    """energies() (numpy, for tests and tools) gives the E and S the step's kernels compute
    (energy_sums.guard_sums, energy_bound.energy_and_scale): gravity in S counts from the lowest
    dynamic body, so the same world 100 km up has the same S."""
    from physics.step.energy_bound import energy_and_scale
    scales = []
    w = physics.World(gravity=(0.0, -9.81))
    w.add_body(physics.Polygon.box(10, 1), kind="static", position=(0.0, height - 0.5))
    low = w.add_body(physics.Polygon.box(1, 1), position=(0.0, height + 0.5))
    w.add_body(physics.Circle(0.3), position=(1.5, height + 3.0), velocity=(1.0, 0.0))
    w.add_spring(low, None, anchor_b=(0.0, height + 4.0), stiffness=20.0, rest_length=2.0)
    for _ in range(5):
        w.step()
        e, s = energies(w)
        ek, sk = energy_and_scale(w._pipeline._guard.end)
        assert e == pytest.approx(ek, rel=1e-9, abs=1e-9 * abs(ek) + 1e-6) and s == pytest.approx(sk, rel=1e-9)
        scales.append(s)
    # the circle (density 1: pi 0.3^2 kg) 2.5 m above the box: about m g 2.5 m of scale at any height
    assert scales[0] >= 0.9 * math.pi * 0.09 * 9.81 * 2.5
    assert scales[0] < 1e3  # not m g 1e5 m
