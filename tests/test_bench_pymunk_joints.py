"""The joint scenes in pymunk (bench/engines/pymunk_joints.py): the benchmark's reference must run
the same machine, so its joints must mean what ours mean (anchors, signs of motors and limits)."""
import math

import numpy as np
import pytest

pytest.importorskip("pymunk")

from bench.desc import load_desc, with_world  # noqa: E402
from bench.engines import build  # noqa: E402
from bench.scenes import JOINT_BENCH  # noqa: E402
from bench.paths import SCENES  # noqa: E402


def sim(name):
    return build("pymunk", with_world(load_desc(SCENES / f"{name}.json"), sleeping=False))


def index(s, name):
    return [b.get("name") for b in s.desc["bodies"]].index(name)


@pytest.mark.parametrize("name", JOINT_BENCH)
def test_every_joint_scene_builds_and_runs_in_pymunk(name):
    s = sim(name)
    assert s.space.constraints
    for _ in range(60):
        s.step()
    com, ang, v, w = s.state()
    assert np.isfinite(com).all() and np.isfinite(w).all()


def test_pymunk_rod_pendulum_period():
    # the 1 m rod of scenes/pendulum.json: T = 2 pi sqrt(2 L / 3 g) (1 + th^2/16 + ...) at 30 deg;
    # a wrong anchor (the centre of mass instead of the origin frame) changes it by far more than 1 %
    s = sim("pendulum")
    i = index(s, "rod0")
    angles = []
    for _ in range(600):
        s.step()
        angles.append(s.state()[1][i])
    x = np.array(angles) - np.mean(angles)
    up = [k + x[k] / (x[k] - x[k + 1]) for k in range(len(x) - 1) if x[k] < 0 <= x[k + 1]]
    period = (up[-1] - up[0]) / (len(up) - 1) / 60.0
    th = math.radians(30)
    exact = 2 * math.pi * math.sqrt(2 / 30.0) * (1 + th ** 2 / 16 + 11 * th ** 4 / 3072)
    assert abs(period / exact - 1) < 0.01, period


def test_pymunk_car_drives_forwards_like_ours():
    # motor_speed is the chassis's relative to the wheel: +12 turns the wheel clockwise, forwards
    s = sim("car")
    i = index(s, "chassis")
    x0 = s.state()[0][i, 0]
    for _ in range(300):
        s.step()
    assert s.state()[0][i, 0] - x0 > 5.0


def test_pymunk_piston_keeps_its_stroke_limits():
    s = sim("piston")
    i = index(s, "piston")
    y0 = s.state()[0][i, 1]
    ys = []
    for _ in range(420):
        s.step()
        ys.append(s.state()[0][i, 1] - y0)
    assert max(ys) < 0.05 + 0.02 and min(ys) > -1.65 - 0.02
    assert abs(s.state()[0][i, 0]) < 0.02  # on its vertical axis
