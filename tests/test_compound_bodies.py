"""Compound and concave bodies in motion, and smooth chains (issue 13).

Bounds and where they come from:
- sliding on a chain: Coulomb friction decelerates a sliding box at mu g exactly (analytic);
  2 % of the speed covers soft_step's contact softness; "no kick" is the issue's 1 cm/s;
- rolling on a chain: a ball rolling without slip keeps its speed (no rolling resistance in
  the model; 1 % over 3 s) and moves vertically as on one flat box (1 cm/s);
- resting: a body at rest sinks at most the linear slop (5 mm, the solver's allowance) plus
  1 mm, and keeps its angle within 1e-3 rad (a Box2D v3 pyramid holds 1e-3 rad as well).
"""
import math

import pytest

import physics

from builders import world

G = 10.0


def flat_chain(segments=50, length=1.0):
    """Ground at y = 0 from x = +L/2 to -L/2 (right to left: solid below)."""
    half = 0.5 * segments * length
    return physics.Chain([(half - k * length, 0.0) for k in range(segments + 1)])


def test_box_slides_over_a_flat_chain_without_snagging():
    w = world()
    w.add_body(flat_chain(), kind="static", friction=0.2)
    box = w.add_body(physics.Polygon.box(1, 1), position=(-20, 0.5), velocity=(5, 0), friction=0.2)
    for _ in range(12):  # settle the first contact (0.2 s)
        w.step()
    v0, t0 = box.velocity[0], w.time
    worst = 0.0
    while w.time < t0 + 2.0:
        w.step()
        worst = max(worst, abs(box.velocity[1]))
        expect = v0 - 0.2 * G * (w.time - t0)
        assert box.velocity[0] == pytest.approx(expect, abs=0.02 * 5)
    assert worst < 0.01
    assert box.position[0] > -20 + 5.0  # it crossed several joints


def test_ball_rolls_over_a_flat_chain_as_over_one_flat_box():
    # a rolling ball's reported vertical speed is -g dt / 2 on any flat ground in soft_step (its
    # contact is found at the start of the step); the joints must add nothing to it
    runs = []
    for ground in (flat_chain(), physics.Polygon.box(60, 1)):
        w = world()
        w.add_body(ground, kind="static", position=(0, 0) if ground.kind == "chain" else (0, -0.5))
        ball = w.add_body(physics.Circle(0.5), position=(-20, 0.5), velocity=(5, 0), angular_velocity=-10)
        trace = []
        for _ in range(192):
            w.step()
            trace.append(ball.velocity)
        runs.append(trace)
    for (vx, vy), (bx, by) in zip(*runs):
        assert abs(vy - by) < 0.01
        assert vx == pytest.approx(5.0, rel=0.01)


def test_chain_loop_holds_a_box_on_top():
    w = world()
    w.add_body(physics.Chain([(-5, -1), (5, -1), (5, 0), (-5, 0)], loop=True), kind="static")  # CCW: solid inside
    top = w.add_body(physics.Polygon.box(1, 1), position=(0, 0.6))
    for _ in range(60):
        w.step()
    assert top.position[1] == pytest.approx(0.5, abs=0.006)


def u_outline(width=2.0, height=1.0, wall=0.2):
    """An upright U (opening up): outer width x height, walls and floor ``wall`` thick."""
    return [(-width / 2, 0), (width / 2, 0), (width / 2, height), (width / 2 - wall, height),
            (width / 2 - wall, wall), (-width / 2 + wall, wall), (-width / 2 + wall, height), (-width / 2, height)]


def test_compound_body_rests_on_its_concave_side():
    w = world()
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    arch = w.add_body(physics.decompose(u_outline()), position=(0.0, 1.2), angle=math.pi)  # upside down
    for _ in range(180):
        w.step()
    # upside down, the rim (y = 1 in body coordinates) is at the bottom: origin at height 1
    assert arch.position[1] == pytest.approx(1.0, abs=0.006)
    assert abs(math.remainder(arch.angle - math.pi, 2 * math.pi)) < 1e-3
    assert abs(arch.velocity[0]) + abs(arch.velocity[1]) < 1e-2


def test_cup_holds_ten_balls_for_ten_seconds():
    w = world()
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    cup = w.add_body(physics.decompose(u_outline(width=3.0, height=2.0, wall=0.2)), position=(0, 0), density=5)
    balls = [w.add_body(physics.Circle(0.2), position=(-1.0 + 0.5 * (k % 5), 0.6 + 0.5 * (k // 5)), restitution=0.2)
             for k in range(10)]
    for _ in range(600):
        w.step()
    for b in balls:
        x, y = cup.world_to_local(b.center_of_mass)
        assert -1.3 <= x <= 1.3 and 0.2 < y < 2.0, (x, y)
    assert abs(cup.angle) < 1e-2
