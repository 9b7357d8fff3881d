"""Integrators and force generators against closed-form answers (seed 7.1-7.2)."""
import math

import numpy as np
import pytest

import physics
from seed_scenes import world

G = 9.81


def projectile(integrator, steps=90, dt=1 / 60):
    w = world("impulse", integrator, dt=dt)
    b = w.add_body(physics.Polygon.box(1, 1), velocity=(3.0, 5.0))
    for _ in range(steps):
        w.step()
    t = steps * dt
    exact = np.array([3.0 * t, 5.0 * t - 0.5 * G * t * t])
    return np.array(b.position) - exact, t, dt


def test_rk4_is_exact_for_constant_gravity():
    err, _, _ = projectile("rk4")
    assert np.abs(err).max() < 1e-9


@pytest.mark.parametrize("integrator,sign", [("symplectic_euler", -1.0), ("euler", 1.0)])
def test_euler_variants_have_their_known_position_error(integrator, sign):
    # x_n = x0 + v0 t + g h^2 n(n -/+ 1)/2: the height error is -/+ g t h / 2, x exact
    err, t, dt = projectile(integrator)
    assert abs(err[0]) < 1e-9
    assert err[1] == pytest.approx(sign * 0.5 * G * t * dt, rel=1e-9)


def oscillator(integrator, k=100.0, c=0.0, x0=0.1, dt=1 / 60):
    """1 kg box on a spring to a world point 1 m to its left (rest 1 m), no gravity."""
    w = world("impulse", integrator, gravity=(0.0, 0.0), dt=dt)
    b = w.add_body(physics.Polygon.box(1, 1), position=(x0, 0.0))
    w.add_spring(b, None, anchor_b=(-1.0, 0.0), stiffness=k, damping=c, rest_length=1.0)
    return w, b


def crossings(xs, ts):
    """Times where x crosses zero upwards (linear interpolation)."""
    out = []
    for i in range(1, len(xs)):
        if xs[i - 1] < 0.0 <= xs[i]:
            out.append(ts[i - 1] + (ts[i] - ts[i - 1]) * (-xs[i - 1]) / (xs[i] - xs[i - 1]))
    return out


def measured_period(integrator, steps=400):
    w, b = oscillator(integrator)
    xs, ts = [], []
    for _ in range(steps):
        w.step()
        xs.append(b.position[0])
        ts.append(w.time)
    up = crossings(xs, ts)
    return (up[-1] - up[0]) / (len(up) - 1)


@pytest.mark.parametrize("integrator,tol", [("rk4", 1e-3), ("symplectic_euler", 2e-2)])
def test_spring_period(integrator, tol):
    period = 2 * math.pi / 10.0
    assert measured_period(integrator) == pytest.approx(period, rel=tol)


def test_explicit_euler_energy_grows_by_theory():
    # explicit Euler on x'' = -w^2 x multiplies the energy by 1 + (w h)^2 every step
    w, b = oscillator("euler")
    e = [w.kinetic_energy() + w.potential_energy()]
    for _ in range(30):
        w.step()
        e.append(w.kinetic_energy() + w.potential_energy())
    ratios = np.array(e[1:]) / np.array(e[:-1])
    assert ratios == pytest.approx(1 + (10.0 / 60) ** 2, rel=1e-9)


def test_damped_oscillator_decay_rate():
    # amplitude ~ exp(-c t / 2m); c = 1 gives 0.5 1/s
    w, b = oscillator("rk4", c=1.0)
    xs, ts = [], []
    for _ in range(300):
        w.step()
        xs.append(b.position[0])
        ts.append(w.time)
    xs = np.array(xs)
    peaks = [i for i in range(1, len(xs) - 1) if xs[i - 1] < xs[i] >= xs[i + 1]]
    rate = -np.polyfit(np.array(ts)[peaks], np.log(xs[peaks]), 1)[0]
    assert rate == pytest.approx(0.5, rel=0.02)


def spring_pair(dt):
    """Two boxes joined corner to corner (mirror-symmetric, never touching)."""
    w = world("impulse", "rk4", gravity=(0.0, 0.0), dt=dt)
    a = w.add_body(physics.Polygon.box(1, 1), position=(0.0, 0.0))
    b = w.add_body(physics.Polygon.box(1, 1), position=(4.0, 0.0))
    w.add_spring(a, b, anchor_a=(0.5, 0.5), anchor_b=(-0.5, 0.5), stiffness=50.0, rest_length=2.5)
    for _ in range(int(round(1.0 / dt))):
        w.step()
    return w, a


def test_spring_between_bodies_is_equal_and_opposite_with_torque():
    w, a = spring_pair(1 / 60)
    assert np.abs(w.linear_momentum()).max() < 1e-12  # equal and opposite forces
    assert a.angular_velocity != 0.0  # off-centre anchors make a torque
    assert abs(w.angular_momentum()) < 1e-12  # and the torques cancel about any point


def test_stiff_spring_is_substepped_and_too_stiff_is_reported():
    w, b = oscillator("symplectic_euler", k=1e5)  # omega dt = 5.3: needs 6 sub-steps
    amp = 0.0
    for _ in range(120):
        w.step()
        amp = max(amp, abs(b.position[0]))
    assert 0.09 < amp < 0.15  # bounded (symplectic Euler at omega h <= 1: stable, energy within ~omega h)
    w, b = oscillator("symplectic_euler", k=1e9)
    before = b.position
    with pytest.raises(physics.SimulationError, match="max_substeps"):
        w.step()
    assert b.position == before


def test_no_spring_stage_without_springs():
    w = world("impulse", "rk4")
    b = w.add_body(physics.Polygon.box(1, 1))
    assert "forces:springs" not in w.info()["stages"]
    w.add_spring(b, None, anchor_b=(0, 2))
    assert "forces:springs" in w.info()["stages"]
