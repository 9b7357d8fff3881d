"""Jointed structures (issue 14): chains and a weld cantilever against the accuracy the issue
demands beyond Box2D v3, plus determinism, sleeping and live mode switching with joints.
Box2D v3 figures: bench/results/box2d_v3_figures.json (``box2d: <id> = value``)."""
import numpy as np
import pytest

import physics
from builders import world
from joint_rigs import MODES, cantilever, hanging_chain, horizontal_chain, separation, tip


def _worst_over(w, joints, seconds, last):
    """Largest joint separation over the final ``last`` seconds of ``seconds``."""
    worst = 0.0
    steps = int(round(seconds / w.dt))
    for k in range(steps):
        w.step()
        if k >= steps - int(round(last / w.dt)):
            worst = max(worst, max(separation(j) for j in joints))
    return worst


@pytest.mark.parametrize("solver", ("soft_step", "sequential_impulse"))
def test_hanging_chain_50_holds(solver):
    # box2d: chain.hanging50_max_separation = 7.0 mm (9..10 s); issue 14: < 1 mm
    w, _, joints = hanging_chain(solver)
    worst = _worst_over(w, joints, 10.0, 1.0)
    assert worst < 1e-3, worst


def test_hanging_chain_with_heavy_end_weight():
    # box2d: chain.hanging50_weight100_max_separation = 29.2 mm; issue 14 (soft_step): < 1 cm
    w, bodies, joints = hanging_chain("soft_step", end_mass_ratio=100.0)
    assert abs(bodies[-1].mass / bodies[0].mass - 100.0) < 1e-9
    worst = _worst_over(w, joints, 10.0, 1.0)
    assert worst < 1e-2, worst


@pytest.mark.parametrize("solver", ("soft_step", "sequential_impulse"))
def test_horizontal_chain_30_after_10s(solver):
    # box2d: chain.horizontal30_separation_10s = 4.3 mm; issue 14: < 5 mm after 10 s
    w, _, joints = horizontal_chain(solver)
    for _ in range(600):
        w.step()
    worst = max(separation(j) for j in joints)
    assert worst < 5e-3, worst


@pytest.mark.parametrize("solver", ("soft_step", "sequential_impulse"))
def test_weld_cantilever_sag(solver):
    # box2d: weld.cantilever_tip_sag_5_10s = 2.05 m (issue 14 quotes 1.75 m); issue 14: < 2 cm
    w, bodies, _ = cantilever(solver)
    y0 = tip(bodies[-1])[1]
    sags = []
    for k in range(600):
        w.step()
        if k >= 300:
            sags.append(y0 - tip(bodies[-1])[1])
    assert max(sags) < 0.02, max(sags)


def test_sequential_joint_solver_is_box2d_like():
    # the sequential setting solves joint by joint as Box2D v3 does: the chain stretches visibly
    # more than with the global solve (what the global solve is for)
    w, _, joints = hanging_chain("soft_step", settings={"joint_solver": "sequential"})
    seq = _worst_over(w, joints, 5.0, 1.0)
    w, _, joints = hanging_chain("soft_step")
    glob = _worst_over(w, joints, 5.0, 1.0)
    assert seq > 3 * glob, (seq, glob)


@pytest.mark.parametrize("solver", MODES)
def test_determinism_with_joints(solver):
    def run():
        w, bodies, joints = horizontal_chain(solver, links=10)
        w.add_joint("prismatic", w.add_body(physics.Circle(0.2), position=(0, 3)), None, axis=(1, 1),
                    motor_speed=1.0, max_motor_force=50.0)
        for _ in range(120):
            w.step()
        return w.state().tobytes()
    assert run() == run()


@pytest.mark.parametrize("solver", ("soft_step", "sequential_impulse"))
def test_jointed_structure_sleeps_and_wakes(solver):
    w = world(solver, sleeping=True)
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    a = w.add_body(physics.Polygon.box(1, 0.2), position=(0, 0.1))
    b = w.add_body(physics.Polygon.box(1, 0.2), position=(1, 0.1))
    w.add_joint("revolute", b, a, anchor=(0.5, 0.1))
    ball = w.add_body(physics.Circle(0.2), position=(1.2, 45.0))  # lands after 3 s
    for _ in range(150):
        w.step()
    assert not a.awake and not b.awake  # it fell asleep as one island
    for _ in range(90):
        w.step()
        if ball.position[1] < 0.45:  # resting on b (radius 0.2 on b's top face at 0.2)
            break
    w.step()
    assert ball.position[1] < 0.45
    assert a.awake and b.awake  # touched on b: the whole island woke, a too


def test_motor_keeps_its_bodies_awake():
    w = world("soft_step", sleeping=True, gravity=(0, 0))
    disc = w.add_body(physics.Circle(0.5))
    j = w.add_joint("revolute", disc, None, motor_speed=0.0, max_motor_torque=10.0)
    for _ in range(200):
        w.step()
    assert not disc.awake
    j.motor_speed = 2.0  # an edit wakes it, and a driving motor keeps it awake
    for _ in range(300):
        w.step()
    assert disc.awake and abs(disc.angular_velocity - 2.0) < 0.02


def test_mode_switching_every_second_keeps_joints_together():
    # issue 14: switching modes every second keeps joint separation bounded (warm starts handed over)
    w, _, joints = hanging_chain("soft_step", links=20)
    w.add_body(physics.Polygon.box(1, 1), position=(2.0, -3.0))
    worst = 0.0
    for second in range(10):
        w.solver = MODES[second % len(MODES)]
        for _ in range(60):
            w.step()
            worst = max(worst, max(separation(j) for j in joints))
    assert np.isfinite(worst)
    assert worst < 0.05, worst
