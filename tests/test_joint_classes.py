"""Typed joint classes (issue 39): one public class per kind, derived from physics/joint_params.py.

Both routes, ``world.add_joint(kind, ...)`` and ``physics.RevoluteJoint(...)``, make the same
joint and a handle of the kind's class; every place that hands out handles (lookups, scene
loading, snapshots) keeps the class; a class has exactly its kind's parameters."""
import numpy as np
import pytest

import physics
from builders import world
from physics import joint_params as jp
from physics.joint_kinds import CLASS_OF
from physics.store.joints import JOINT_FIELDS, JOINT_KINDS

CLASSES = {"revolute": physics.RevoluteJoint, "prismatic": physics.PrismaticJoint, "weld": physics.WeldJoint,
           "distance": physics.DistanceJoint, "wheel": physics.WheelJoint, "motor": physics.MotorJoint,
           "mouse": physics.MouseJoint, "rotary": physics.RotaryJoint}

# non-default values for each kind (body_b is None for the mouse joint)
KEYWORDS = {
    "revolute": dict(anchor=(0.5, 0.1), lower_angle=-0.4, upper_angle=0.7, motor_speed=1.5, max_motor_torque=20.0,
                     spring_hertz=2.0, spring_damping_ratio=0.3),
    "prismatic": dict(anchor=(0.2, 0.0), axis=(1.0, 1.0), lower=-0.5, upper=0.25, motor_speed=-0.5,
                      max_motor_force=12.0, spring_hertz=1.0, spring_damping_ratio=0.1),
    "weld": dict(anchor=(0.5, 0.0), linear_hertz=3.0, angular_hertz=2.0, damping_ratio=0.4),
    "distance": dict(anchor_a=(0.1, 0.0), anchor_b=(1.2, 0.3), min_length=0.5, max_length=2.0, spring_hertz=1.5,
                     spring_damping_ratio=0.2),
    "wheel": dict(anchor=(1.0, 0.0), axis=(0.0, 1.0), spring_hertz=5.0, spring_damping_ratio=0.5, motor_speed=3.0,
                  max_motor_torque=7.0, lower=-0.2, upper=0.2),
    "motor": dict(linear_offset=(0.3, -0.2), angular_offset=0.25, max_force=40.0, max_torque=9.0),
    "mouse": dict(target=(2.0, 1.0), hertz=4.0, damping_ratio=0.9, max_force=300.0),
    "rotary": dict(anchor=(0.5, 0.0), lower_angle=-0.3, upper_angle=0.6, motor_speed=2.0, max_motor_torque=4.0,
                   spring_hertz=1.0, spring_damping_ratio=0.2),
}


def _pair(w):
    a = w.add_body(physics.Polygon.box(1, 0.2), position=(0, 0), name="arm")
    b = w.add_body(physics.Polygon.box(1, 0.2), position=(1, 0), angle=0.1, name="forearm")
    return a, b


def _row(j):
    J, s = j._J, j._s
    return {f: np.array(getattr(J, f)[s]) for f in JOINT_FIELDS}


@pytest.mark.parametrize("kind", JOINT_KINDS)
def test_both_routes_give_the_kinds_class_and_the_same_row(kind):
    cls = CLASSES[kind]
    w1, w2 = world(), world()
    (a1, b1), (a2, b2) = _pair(w1), _pair(w2)
    other1, other2 = (None, None) if kind == "mouse" else (b1, b2)
    j1 = w1.add_joint(kind, a1, other1, name="j", break_force=50.0, **KEYWORDS[kind])
    j2 = cls(a2, other2, name="j", break_force=50.0, **KEYWORDS[kind])
    assert type(j1) is cls and type(j2) is cls and cls is CLASS_OF[kind]
    assert isinstance(j2, physics.Joint) and j2.kind == kind
    assert (j2.body_a, j2.body_b, j2.name, j2.break_force) == (a2, other2, "j", 50.0)
    assert w2.joints == [j2] and w2.joint("j") is j2 and type(w2.joints[0]) is cls
    r1, r2 = _row(j1), _row(j2)
    assert r1.keys() == r2.keys()
    for f in r1:
        assert np.array_equal(r1[f], r2[f], equal_nan=True), f
    for name in jp.PARAMS[kind]:
        assert getattr(j1, name) == getattr(j2, name), name
    w2.remove(j2)
    assert w2.joints == [] and not j2.alive


def test_the_classes_are_public_and_one_per_kind():
    assert set(CLASS_OF) == set(JOINT_KINDS)
    for kind, cls in CLASS_OF.items():
        assert cls.__name__ in physics.__all__ and getattr(physics, cls.__name__) is cls
        assert issubclass(cls, physics.Joint) and cls.__doc__.strip()
    assert len(set(CLASS_OF.values())) == len(JOINT_KINDS)


def test_the_constructor_rejects_what_add_joint_rejects():
    w = world()
    a, b = _pair(w)
    with pytest.raises(TypeError, match=r"RevoluteJoint: .*'spin'.*'whirl'"):
        physics.RevoluteJoint(a, b, spin=1.0, whirl=2)
    with pytest.raises(TypeError, match="'max_motor_force'"):
        physics.RevoluteJoint(a, b, max_motor_force=1.0)  # another kind's parameter
    bad = [dict(max_motor_torque=-1.0), dict(lower_angle=0.5, upper_angle=0.1), dict(anchor=(0, float("nan"))),
           dict(break_force=0.0), dict(collide_connected=1)]
    for kw in bad:
        with pytest.raises(ValueError) as typed:
            physics.RevoluteJoint(a, b, **kw)
        with pytest.raises(ValueError) as plain:
            w.add_joint("revolute", a, b, **kw)
        assert str(typed.value) == str(plain.value)
    with pytest.raises(ValueError, match="upper_angle"):
        physics.RevoluteJoint(a, b, lower_angle=0.5, upper_angle=0.1)
    with pytest.raises(ValueError, match="max_motor_torque"):
        physics.RevoluteJoint(a, b, max_motor_torque=-1.0)
    assert w.joints == []  # nothing was added by a refused call


def test_the_constructor_needs_bodies_of_one_world():
    w, elsewhere = world(), world()
    a, b = _pair(w)
    stranger = elsewhere.add_body(physics.Circle(0.2), position=(5, 5))
    with pytest.raises(ValueError, match="body_b"):
        physics.RevoluteJoint(a, stranger)
    with pytest.raises(ValueError, match="body_a"):
        physics.RevoluteJoint(None, b)
    with pytest.raises(ValueError, match="body_a"):
        physics.WeldJoint("arm", b)
    with pytest.raises(ValueError, match="body_b"):
        physics.MouseJoint(a, b, target=(1, 1))
    w.remove(b)
    with pytest.raises(ValueError, match="body_a"):
        physics.DistanceJoint(b, a)
    assert w.joints == [] and elsewhere.joints == []
    j = physics.WeldJoint(stranger)  # body_b None: held to the world, added to body_a's world
    assert elsewhere.joints == [j] and j.body_b is None


@pytest.mark.parametrize("kind", JOINT_KINDS)
def test_a_kinds_class_has_exactly_its_parameters(kind):
    cls = CLASS_OF[kind]
    mine = jp.PARAMS[kind]
    others = {n for params in jp.PARAMS.values() for n in params} - set(mine)
    w = world()
    a, b = _pair(w)
    j = cls(a, None if kind == "mouse" else b)
    for name, p in mine.items():
        assert isinstance(getattr(cls, name), property), name
        if name != "length":  # a distance joint's length is the readout: the distance now
            assert getattr(cls, name).__doc__.startswith(p.doc), name
        assert name in dir(j) and name in cls.__doc__ and f"default {p.default!r}" in cls.__doc__
    for name in others:
        assert not hasattr(cls, name) and name not in dir(j), name
        with pytest.raises(AttributeError, match=f"a {kind} joint has no parameter '{name}'"):
            getattr(j, name)
        with pytest.raises(AttributeError, match=f"a {kind} joint has no parameter '{name}'"):
            setattr(j, name, 1.0)


def test_readouts_belong_to_the_kinds_that_have_them():
    w = world()
    a, b = _pair(w)
    hinge = physics.RevoluteJoint(a, b, anchor=(0.5, 0))
    slider = physics.PrismaticJoint(a, b, axis=(1, 0))
    assert "angle" in dir(hinge) and "translation" not in dir(hinge) and "motor_force" not in dir(hinge)
    assert {"translation", "axis", "motor_force"} <= set(dir(slider)) and "motor_torque" not in dir(slider)
    with pytest.raises(AttributeError, match="no translation"):
        hinge.translation
    assert slider.translation == 0.0 and hinge.angle == 0.0  # both read 0 where they were made
    a.position = (0.3, 0.0)
    assert slider.translation == pytest.approx(0.3)


def _one_of_each(w):
    a, b = _pair(w)
    for kind in JOINT_KINDS:
        CLASS_OF[kind](a, None if kind == "mouse" else b, name=kind, **KEYWORDS[kind])


def test_the_class_survives_saving_and_loading(tmp_path):
    w = world()
    _one_of_each(w)
    path = tmp_path / "joints.json"
    physics.save_scene(w, path)
    back = physics.load_scene(path)
    assert [type(j) for j in back.joints] == [type(j) for j in w.joints] == [CLASS_OF[k] for k in JOINT_KINDS]
    for kind in JOINT_KINDS:
        j = back.joint(kind)
        assert type(j) is CLASS_OF[kind]
        for name in jp.PARAMS[kind]:
            assert getattr(j, name) == getattr(w.joint(kind), name), (kind, name)


def test_the_class_survives_a_snapshot_restore():
    w = world()
    _one_of_each(w)
    before = list(w.joints)
    snap = w.snapshot()
    hinge = w.joint("revolute")
    hinge.motor_speed = 9.0
    for _ in range(10):
        w.step()
    w.restore(snap)
    assert w.joints == before and [type(j) for j in w.joints] == [CLASS_OF[k] for k in JOINT_KINDS]
    assert w.joint("revolute") is hinge and hinge.motor_speed == KEYWORDS["revolute"]["motor_speed"]
    other = world()  # built by add_joint: the same ids, so the snapshot restores into it
    a, b = _pair(other)
    for kind in JOINT_KINDS:
        other.add_joint(kind, a, None if kind == "mouse" else b, name=kind, **KEYWORDS[kind])
    other.restore(snap)
    assert [type(j) for j in other.joints] == [type(j) for j in before]


def _pendulum(typed: bool):
    w = world()
    top = w.add_body(physics.Polygon.box(0.2, 1.0), position=(1.0, 2.5), angle=-0.3)
    bob = w.add_body(physics.Circle(0.25), position=(1.8, 1.7))
    if typed:
        physics.RevoluteJoint(top, None, anchor=(0.8, 3.0))
        physics.RevoluteJoint(bob, top, anchor=(1.2, 2.0), max_motor_torque=0.5)
    else:
        w.add_joint("revolute", top, None, anchor=(0.8, 3.0))
        w.add_joint("revolute", bob, top, anchor=(1.2, 2.0), max_motor_torque=0.5)
    for _ in range(60):
        w.step()
    return [(b.position, b.angle, b.velocity) for b in (top, bob)]


def test_a_pendulum_built_with_the_class_steps_bit_for_bit_as_with_add_joint():
    typed, plain = _pendulum(True), _pendulum(False)
    start = [((1.0, 2.5), -0.3), ((1.8, 1.7), 0.0)]
    assert [(p, q) for p, q, _ in plain] != start  # it swung: the comparison is not of two rests
    assert typed == plain
