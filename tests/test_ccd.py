"""Continuous collision: speculative contacts stop fast bodies at thin walls (issue 5).

The geometry stage fattens AABBs by the velocity, the narrow phase keeps
points up to the speculative margin, and each solver lets a speculative
point (depth < 0) close its gap within the step but never pass it.
"""
import math

import pytest

import physics

SOLVERS = ("soft_step", "sequential_impulse")


def shoot(solver, speed, restitution=0.0, size=0.2, angle=0.0, steps=90, dt=1 / 60):
    w = physics.World(gravity=(0.0, 0.0), dt=dt, solver=solver, sleeping=False)
    w.add_body(physics.Polygon.box(0.2, 4.0), kind="static", position=(0.0, 0.0))
    b = w.add_body(physics.Polygon.box(size, size), position=(-5.0, 0.3), angle=angle,
                   velocity=(speed, 0.0), restitution=restitution)
    xmax = -math.inf
    for _ in range(steps):
        w.step()
        xmax = max(xmax, b.position[0])
        assert all(math.isfinite(c) for c in b.position + b.velocity)
    return b, xmax


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("speed", [200.0, 1000.0])
def test_fast_box_stops_at_thin_wall(solver, speed):
    b, xmax = shoot(solver, speed)
    # the wall's left face is at x = -0.1; the box's centre may come no closer than 0.1 from it
    assert xmax < -0.1 - 0.1 + 0.02, f"tunnelled or overlapped: max x {xmax}"
    assert b.position[0] < 0.0
    assert b.velocity[0] <= 1e-6  # stopped, or moving back


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("speed", [200.0, 1000.0])
def test_fast_box_bounces_from_thin_wall(solver, speed):
    b, xmax = shoot(solver, speed, restitution=0.5)
    assert xmax < -0.18
    assert b.velocity[0] < -0.3 * speed, "a restitution of 0.5 should send it back at about half speed"
    assert b.position[0] < -0.2


@pytest.mark.parametrize("solver", SOLVERS)
def test_fast_rotated_box_does_not_tunnel(solver):
    b, xmax = shoot(solver, 300.0, angle=0.6)
    assert xmax < -0.1
    assert b.position[0] < -0.1


@pytest.mark.parametrize("solver", SOLVERS)
def test_fast_circle_does_not_tunnel(solver):
    w = physics.World(gravity=(0.0, 0.0), solver=solver, sleeping=False)
    w.add_body(physics.Polygon.box(0.2, 4.0), kind="static", position=(0.0, 0.0))
    c = w.add_body(physics.Circle(0.1), position=(-5.0, 0.0), velocity=(500.0, 0.0))
    for _ in range(60):
        w.step()
    assert c.position[0] < -0.15


@pytest.mark.parametrize("solver", SOLVERS)
def test_falling_fast_onto_thin_floor(solver):
    w = physics.World(gravity=(0.0, -10.0), solver=solver, sleeping=False)
    w.add_body(physics.Polygon.box(10.0, 0.2), kind="static", position=(0.0, 0.0))
    b = w.add_body(physics.Polygon.box(0.2, 0.2), position=(0.0, 20.0), velocity=(0.0, -400.0))
    for _ in range(120):
        w.step()
    assert b.position[1] > 0.15
    assert abs(b.velocity[1]) < 0.5
