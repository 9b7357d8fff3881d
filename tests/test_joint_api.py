"""The joint API and scene format of issue 14: names, validation, removal, live edits, readouts,
collide_connected, the stage list, scene files (errors with JSON paths, exact round trips)."""
import json
import math

import numpy as np
import pytest

import physics
from builders import world
from physics.scene import scene_from_dict, scene_to_dict


def _pair(w=None):
    w = w or world()
    a = w.add_body(physics.Polygon.box(1, 0.2), position=(0, 0), name="arm")
    b = w.add_body(physics.Polygon.box(1, 0.2), position=(1, 0), name="forearm")
    return w, a, b


def test_add_joint_with_the_issue_keywords():
    w, a, b = _pair()
    j = w.add_joint("revolute", a, b, anchor=(0.5, 0.0), lower_angle=-0.5, upper_angle=0.5, motor_speed=2.0,
                    max_motor_torque=50.0, spring_hertz=0.0, spring_damping_ratio=0.0, collide_connected=False,
                    break_force=None, break_torque=None, name="hinge")
    assert isinstance(j, physics.Joint)
    assert (j.kind, j.body_a, j.body_b, j.name) == ("revolute", a, b, "hinge")
    assert w.joint("hinge") is j and w.joints == [j]
    assert (j.lower_angle, j.upper_angle, j.motor_speed, j.max_motor_torque) == (-0.5, 0.5, 2.0, 50.0)
    w.add_joint("prismatic", a, b, anchor=(0, 0), axis=(1, 0), lower=-1.0, upper=1.0, motor_speed=0.0,
                max_motor_force=0.0, spring_hertz=0.0, spring_damping_ratio=0.0)
    w.add_joint("weld", a, b, anchor=(0, 0), linear_hertz=0.0, angular_hertz=0.0, damping_ratio=0.0)
    d = w.add_joint("distance", a, b, anchor_a=(0, 0), anchor_b=(0, 2), length=None, min_length=None,
                    max_length=None, spring_hertz=0.0, spring_damping_ratio=0.0)
    assert d.rest_length == pytest.approx(2.0)
    w.add_joint("wheel", a, b, anchor=(1, 0), axis=(0, 1), spring_hertz=4.0, spring_damping_ratio=0.7,
                motor_speed=0.0, max_motor_torque=0.0, lower=None, upper=None)
    w.add_joint("motor", a, b, linear_offset=(0, 0), angular_offset=0.0, max_force=100.0, max_torque=100.0)
    m = w.add_joint("mouse", a, None, target=(3, 4), hertz=5.0, damping_ratio=0.7, max_force=1000.0)
    m.target = (1.0, 2.0)
    assert m.target == (1.0, 2.0)
    assert len(w.joints) == 7
    for _ in range(5):
        w.step()
    assert all(np.isfinite(x.reaction_force).all() for x in w.joints)


@pytest.mark.parametrize("kw, field", [
    (dict(lower_angle=float("nan")), "lower_angle"),
    (dict(max_motor_torque=-1.0), "max_motor_torque"),
    (dict(lower_angle=1.0, upper_angle=0.0), "upper_angle"),
    (dict(break_force=0.0), "break_force"),
    (dict(anchor=(0, "x")), "anchor"),
])
def test_bad_values_name_the_field(kw, field):
    w, a, b = _pair()
    with pytest.raises(ValueError, match=field):
        w.add_joint("revolute", a, b, **kw)
    assert w.joints == []  # nothing half-added


def test_bad_kind_body_and_keyword():
    w, a, b = _pair()
    with pytest.raises(ValueError, match="kind"):
        w.add_joint("hinge", a, b)
    with pytest.raises(ValueError, match="body_b"):
        w.add_joint("revolute", a, a)
    with pytest.raises(TypeError, match="max_motor_force"):
        w.add_joint("revolute", a, b, max_motor_force=1.0)


def test_live_edits_are_validated():
    w, a, b = _pair()
    j = w.add_joint("revolute", a, b, anchor=(0.5, 0))
    j.motor_speed = 4.0
    assert j.motor_speed == 4.0
    with pytest.raises(ValueError, match="max_motor_torque"):
        j.max_motor_torque = -3
    with pytest.raises(ValueError, match="upper_angle"):
        j.lower_angle = 0.2
        j.upper_angle = 0.1
    with pytest.raises(AttributeError):
        j.max_motor_force = 1.0


def test_remove_joint_and_body():
    w, a, b = _pair()
    c = w.add_body(physics.Circle(0.3), position=(3, 0))
    j1 = w.add_joint("revolute", a, b, anchor=(0.5, 0), name="j1")
    j2 = w.add_joint("distance", b, c, name="j2")
    j3 = w.add_joint("weld", c, None, name="j3")
    w.remove(j1)
    assert not j1.alive and set(w.joints) == {j2, j3}
    w.remove(a)  # swap-remove moves the last body into a's slot
    w.remove(b)  # removes j2 with it
    assert w.joints == [j3] and j3.body_a is c
    with pytest.raises(KeyError):
        w.joint("j2")
    for _ in range(30):
        w.step()
    assert abs(c.position[0] - 3.0) < 1e-6  # still welded where it was


def test_joined_bodies_do_not_collide_unless_asked():
    def overlap_push(collide):
        w = world(gravity=(0, 0))
        a = w.add_body(physics.Polygon.box(1, 1), position=(0, 0))
        b = w.add_body(physics.Polygon.box(1, 1), position=(0.5, 0))
        w.add_joint("distance", a, b, max_length=5.0, collide_connected=collide)
        for _ in range(30):
            w.step()
        return b.position[0] - a.position[0]
    assert overlap_push(False) == pytest.approx(0.5, abs=1e-9)
    assert overlap_push(True) > 0.9


def test_stages_show_joints_only_when_present():
    w, a, b = _pair()
    assert not any(s.startswith("joints") for s in w.info()["stages"])
    j = w.add_joint("revolute", a, b)
    assert any(s.startswith("joints") for s in w.info()["stages"])
    w.remove(j)
    assert not any(s.startswith("joints") for s in w.info()["stages"])


def test_readouts():
    w = world(gravity=(0, 0))
    # turning about the pivot at 1 rad/s from the start (the centre moves at 0.5 m/s)
    a = w.add_body(physics.Polygon.box(1, 0.2), position=(0.5, 0), velocity=(0, 0.5), angular_velocity=1.0)
    j = w.add_joint("revolute", a, None, anchor=(0, 0))
    for _ in range(30):
        w.step()
    assert j.angle == pytest.approx(0.5, rel=1e-3)
    assert j.speed == pytest.approx(1.0, rel=1e-3)
    # centripetal: the joint pulls a towards the pivot with m w^2 r
    assert np.hypot(*j.reaction_force) == pytest.approx(a.mass * 0.5, rel=0.02)


def _scene(joints, bodies=None):
    return {"format": "stelkropp.scene", "version": 1,
            "bodies": bodies or [{"name": "arm", "shape": {"box": [1, 0.2]}, "position": [0.5, 0]},
                                 {"name": "rod", "shape": {"box": [1, 0.2]}, "position": [1.5, 0]}],
            "joints": joints}


def test_scene_round_trip_is_exact():
    w = world()
    # bodies whose origin is their centre of mass: what is tested here is the joints' exactness
    a = w.add_body(physics.Polygon.box(1.0, 0.4), position=(0.1, 0.3), angle=0.3, name="a")
    b = w.add_body(physics.Circle(0.3), position=(1.7, -0.2), angle=-1.1, name="b")
    w.add_joint("revolute", a, b, anchor=(0.77, 0.13), lower_angle=-0.3, max_motor_torque=2.0, name="h")
    w.add_joint("prismatic", b, None, anchor=(1.3, 0.1), axis=(0.3, 0.7), upper=0.4, break_force=50.0)
    w.add_joint("distance", a, None, anchor_b=(0.0, 3.0), max_length=3.5, collide_connected=True)
    w.add_joint("wheel", a, b, anchor=(1.7, -0.2), axis=(0.1, 1.0))
    w.add_joint("weld", b, a, linear_hertz=3.0)
    w.add_joint("motor", a, b, linear_offset=(0.2, 0.1), angular_offset=0.4)
    data = json.loads(json.dumps(scene_to_dict(w)))
    w2 = scene_from_dict(data)
    assert scene_to_dict(w2) == data
    assert w.state().tobytes() == w2.state().tobytes()
    J, J2 = w._store.joints, w2._store.joints
    for f in ("la", "lb", "axis", "ref", "length", "lower", "upper", "motor_speed", "max_motor", "hertz", "offset"):
        assert getattr(J.view, f)[: J.n].tobytes() == getattr(J2.view, f)[: J2.n].tobytes(), f
    for _ in range(20):
        w.step()
        w2.step()
    assert w.state().tobytes() == w2.state().tobytes()


@pytest.mark.parametrize("joint, path", [
    ({"kind": "hinge", "a": "arm"}, "joints[0].kind"),
    ({"kind": "revolute", "a": "nobody"}, "joints[0].a"),
    ({"kind": "revolute", "a": "arm", "b": "ghost"}, "joints[0].b"),
    ({"kind": "revolute", "a": "arm", "max_motor_force": 1}, "joints[0].max_motor_force"),
    ({"kind": "revolute", "a": "arm", "max_motor_torque": -1}, "joints[0].max_motor_torque"),
    ({"kind": "revolute", "a": "arm", "motor_speed": "fast"}, "joints[0].motor_speed"),
    ({"kind": "revolute", "a": "arm", "lower_angle": 1, "upper_angle": 0}, "joints[0].upper_angle"),
    ({"kind": "distance", "a": "arm", "b": "rod", "length": -1}, "joints[0].length"),
])
def test_scene_errors_name_the_json_path(joint, path):
    with pytest.raises(physics.SceneError) as err:
        scene_from_dict(_scene([joint]))
    assert any(p == path for p, _ in err.value.problems), err.value.problems


def test_scene_joint_by_world_anchor():
    w = scene_from_dict(_scene([{"kind": "revolute", "a": "arm", "b": "rod", "anchor": [1.0, 0.0], "name": "elbow"}]))
    j = w.joint("elbow")
    assert j.anchor_a == pytest.approx((1.0, 0.0)) and j.anchor_b == pytest.approx((1.0, 0.0))
    assert math.isclose(j.reference_angle, 0.0)
