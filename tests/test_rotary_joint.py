"""The rotary joint: the relative angle of two bodies alone (an angular spring, a motor, angle
limits), no point held.  pymunk's DampedRotarySpring, SimpleMotor and RotaryLimitJoint in one.

Each figure is an analytic answer: a motor of at most T N m spins a body of inertia I up at
T / I rad/s^2; an undamped angular spring of f Hz swings with period 1 / f and can never swing
wider than its start's energy allows, w0 / (2 pi f); a joint between two free bodies keeps their
total angular momentum (zero from rest) and moves no centre of mass."""
import math

import numpy as np
import pytest
from builders import world

import physics
from physics import joint_params as jp

MODES = ("soft_step", "sequential_impulse", "impulse", "penalty", "hybrid")
DT = 1 / 60


def _disc(w, position=(0.0, 0.0)):
    return w.add_body(physics.Circle(0.5), position=position)


@pytest.mark.parametrize("mode", MODES)
def test_the_motor_spins_a_body_up_at_torque_over_inertia(mode):
    w = world(mode, gravity=(0.0, 0.0))
    d = _disc(w)
    j = physics.RotaryJoint(d, None, motor_speed=2.0, max_motor_torque=0.1)
    for _ in range(60):
        w.step()
    expected = 0.1 / d.inertia * 1.0          # one second at the torque bound, below the target speed
    assert d.angular_velocity == pytest.approx(expected, rel=1e-6)
    assert j.motor_torque == pytest.approx(0.1, rel=1e-6)
    for _ in range(120):                      # then held at the target speed
        w.step()
    assert d.angular_velocity == pytest.approx(2.0, abs=1e-6)
    assert j.speed == pytest.approx(2.0, abs=1e-6)


@pytest.mark.parametrize("mode", MODES)
def test_an_undamped_spring_swings_at_its_frequency_and_never_wider_than_its_energy(mode):
    w = world(mode, gravity=(0.0, 0.0))
    d = _disc(w)
    physics.RotaryJoint(d, None, spring_hertz=2.0)
    d.angular_velocity = 3.0
    d.velocity = (1.0, 0.5)
    angles = []
    for _ in range(180):
        w.step()
        angles.append(d.angle)
    angles = np.array(angles)
    t = np.arange(1, 181) * DT
    crossings = t[np.nonzero(np.diff(np.sign(angles)) != 0)[0]]
    period = 2.0 * np.mean(np.diff(crossings))
    assert period == pytest.approx(0.5, abs=DT / 4)                 # 1 / f
    bound = 3.0 / (2.0 * math.pi * 2.0)                              # w0 / (2 pi f)
    assert np.abs(angles).max() <= bound * 1.001
    assert np.abs(angles).max() >= 0.8 * bound                       # it does swing (soft solvers lose some)
    # no point is held: the centre of mass flies on at its start velocity
    assert d.position == pytest.approx((3.0, 1.5), abs=1e-9)


@pytest.mark.parametrize("mode", MODES)
def test_the_limits_stop_a_spinning_body(mode):
    w = world(mode, gravity=(0.0, 0.0))
    d = _disc(w)
    j = physics.RotaryJoint(d, None, lower_angle=-0.5, upper_angle=0.5)
    d.angular_velocity = 5.0
    seen = []
    for _ in range(240):
        w.step()
        seen.append(j.angle)
    assert max(seen) == pytest.approx(0.5, abs=0.01)       # reached the upper limit and held there
    assert min(seen) >= -0.5 - 0.01
    assert abs(d.angular_velocity) < 0.05


@pytest.mark.parametrize("mode", MODES)
def test_between_two_free_bodies_it_keeps_angular_momentum_and_holds_no_point(mode):
    w = world(mode, gravity=(0.0, 0.0))
    a = _disc(w)
    b = w.add_body(physics.Polygon.box(2.0, 0.4), position=(3.0, 0.0))
    j = w.add_joint("rotary", a, b, motor_speed=3.0, max_motor_torque=50.0)
    for _ in range(120):
        w.step()
    assert a.angular_velocity - b.angular_velocity == pytest.approx(3.0, abs=1e-6)
    assert a.inertia * a.angular_velocity + b.inertia * b.angular_velocity == pytest.approx(0.0, abs=1e-9)
    assert a.position == pytest.approx((0.0, 0.0), abs=1e-12)
    assert b.position == pytest.approx((3.0, 0.0), abs=1e-12)
    assert j.reaction_force == pytest.approx((0.0, 0.0), abs=1e-12)


def test_its_angular_rows_are_the_revolute_joints_without_the_point():
    """A revolute joint pinned at a free disc's centre holds a point the disc does not leave, so
    its angle follows the same spring, motor and limits as a rotary joint's."""
    out = []
    for kind in ("rotary", "revolute"):
        w = world("soft_step", gravity=(0.0, 0.0))
        d = _disc(w)
        w.add_joint(kind, d, None, anchor=(0.0, 0.0), spring_hertz=1.5, spring_damping_ratio=0.1,
                    motor_speed=-1.0, max_motor_torque=0.05, lower_angle=-0.3, upper_angle=0.4)
        d.angular_velocity = 4.0
        angles = []
        for _ in range(240):
            w.step()
            angles.append(d.angle)
        out.append(np.array(angles))
    assert np.allclose(out[0], out[1], rtol=0, atol=1e-12)


def test_the_class_and_the_declaration():
    w = world()
    a, b = _disc(w), _disc(w, (2.0, 0.0))
    j = physics.RotaryJoint(a, b, anchor=(1.0, 0.0), upper_angle=0.2, name="r")
    assert type(j) is physics.RotaryJoint and isinstance(j, physics.Joint) and j.kind == "rotary"
    assert "RotaryJoint" in physics.__all__ and w.joint("r") is j
    assert set(jp.PARAMS["rotary"]) == {"lower_angle", "upper_angle", "motor_speed", "max_motor_torque",
                                        "spring_hertz", "spring_damping_ratio"}
    assert j.upper_angle == 0.2 and j.lower_angle is None and j.angle == 0.0
    with pytest.raises(AttributeError, match="translation"):
        j.translation
    with pytest.raises(ValueError, match="upper_angle"):
        j.upper_angle = "x"
    with pytest.raises(ValueError, match="upper_angle"):
        j.lower_angle = 0.5                       # above the upper limit
    with pytest.raises(TypeError, match="axis"):
        physics.RotaryJoint(a, b, axis=(1.0, 0.0))


def test_a_saved_rotary_joint_loads_the_same(tmp_path):
    w = world()
    a, b = _disc(w), _disc(w, (2.0, 0.0))
    b.angle = 0.3
    physics.RotaryJoint(a, b, spring_hertz=3.0, motor_speed=1.0, max_motor_torque=2.0, lower_angle=-0.1,
                        name="r")
    for _ in range(30):
        w.step()
    path = tmp_path / "rotary.json"
    physics.save_scene(w, path)
    back = physics.load_scene(path)
    j0, j1 = w.joint("r"), back.joint("r")
    assert type(j1) is physics.RotaryJoint
    for name in [*jp.PARAMS["rotary"], "reference_angle", "local_anchor_a", "local_anchor_b", "angle"]:
        assert getattr(j1, name) == getattr(j0, name), name
