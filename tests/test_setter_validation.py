"""Setters refuse what they would silently misuse, with a ValueError naming the field (issue 20, items 3, 5)."""
import numpy as np
import pytest

import physics
from physics.settings import UnknownSetting

HUGE = 10 ** 400  # an int beyond the float range: float() raises OverflowError


def world_with_body():
    w = physics.World()
    b = w.add_body(physics.Polygon.box(1, 1), position=(0, 1), name="box")
    s = w.add_spring(b, None, anchor_b=(0, 3), stiffness=10.0, name="hook")
    return w, b, s


# (target, attribute, field named in the message)
SETTERS = [
    ("world", "dt", "dt"), ("world", "time", "time"), ("world", "gravity", "gravity"),
    ("world", "linear_slop", "linear_slop"), ("world", "speculative_distance", "speculative_distance"),
    ("world", "sleep_linear", "sleep_linear"), ("world", "time_to_sleep", "time_to_sleep"),
    ("body", "position", "position"), ("body", "angle", "angle"), ("body", "velocity", "velocity"),
    ("body", "angular_velocity", "angular_velocity"), ("body", "density", "density"),
    ("body", "restitution", "restitution"), ("body", "friction", "friction"),
    ("spring", "stiffness", "stiffness"), ("spring", "damping", "damping"),
    ("spring", "rest_length", "rest_length"), ("spring", "anchor_a", "anchor_a"),
]
PAIRS = {"gravity", "position", "velocity", "anchor_a"}


def target(kind):
    w, b, s = world_with_body()
    return w, {"world": w, "body": b, "spring": s}[kind]


@pytest.mark.parametrize("kind,attr,field", SETTERS)
def test_integer_beyond_float_range_is_a_value_error_naming_the_field(kind, attr, field):
    """A 400-digit integer gave OverflowError from float(); the message names the field and
    does not print the 400 digits."""
    w, obj = target(kind)
    value = (HUGE, 0) if attr in PAIRS else HUGE
    before = getattr(obj, attr)
    with pytest.raises(ValueError, match=field) as info:
        setattr(obj, attr, value)
    assert len(str(info.value)) < 300
    assert getattr(obj, attr) == before


@pytest.mark.parametrize("kind,attr,field", SETTERS)
@pytest.mark.parametrize("text", ["2", b"2", "nan"])
def test_strings_and_bytes_are_not_numbers(kind, attr, field, text):
    """float("2") and float(b"2") succeed, so strings and bytes were accepted as numbers."""
    w, obj = target(kind)
    value = (text, 0) if attr in PAIRS else text
    with pytest.raises(ValueError, match=field):
        setattr(obj, attr, value)


@pytest.mark.parametrize("value", ["false", "off", 0, 1, None, "yes"])
def test_sleeping_takes_only_booleans(value):
    """``world.sleeping = "false"`` turned sleeping on (bool("false") is True)."""
    w, _, _ = world_with_body()
    w.sleeping = False
    with pytest.raises(ValueError, match="sleeping"):
        w.sleeping = value
    assert w.sleeping is False


def test_numpy_values_are_numbers_and_flags():
    """numpy.int64 was refused for integer settings; numpy scalars are accepted everywhere."""
    w, b, _ = world_with_body()
    w.settings["substeps"] = np.int64(8)
    assert w.settings["substeps"] == 8 and type(w.settings["substeps"]) is int
    w.settings["contact_hertz"] = np.float32(30.0)
    assert w.settings["contact_hertz"] == 30.0
    w.sleeping = np.bool_(False)
    assert w.sleeping is False
    b.density = np.int64(3)
    assert b.density == 3.0
    w.time = np.float64(2.5)
    assert w.time == 2.5


@pytest.mark.parametrize("value", [float("nan"), float("inf"), -1.0, "1", None])
def test_time_is_validated(value):
    w, _, _ = world_with_body()
    with pytest.raises(ValueError, match="time"):
        w.time = value
    assert w.time == 0.0


def test_unknown_setting_is_a_key_error_and_a_value_error_naming_it():
    w, _, _ = world_with_body()
    for probe in (lambda: w.settings["no_such_thing"], lambda: w.settings.__setitem__("no_such_thing", 1)):
        with pytest.raises(UnknownSetting) as info:
            probe()
        assert isinstance(info.value, KeyError) and isinstance(info.value, ValueError)
        assert "no_such_thing" in str(info.value) and "soft_step" in str(info.value)
    with pytest.raises(UnknownSetting):
        w.settings[["unhashable"]]


def test_failing_update_applies_nothing():
    """settings.update() applied the keys before the bad one."""
    w, _, _ = world_with_body()
    before = w.settings.to_dict()
    with pytest.raises(ValueError, match="iterations"):
        w.settings.update({"substeps": 8, "contact_hertz": 30.0, "iterations": "many"})
    with pytest.raises(UnknownSetting):
        w.settings.update(substeps=8, bogus=1)
    assert w.settings.to_dict() == before
    w.settings.update({"substeps": 8}, iterations=2)
    assert w.settings["substeps"] == 8 and w.settings["iterations"] == 2


@pytest.mark.parametrize("value", [[], {}, {"a": 1}, set()])
def test_unhashable_choices_name_their_field(value):
    """An unhashable solver or kind gave a TypeError ('unhashable type') naming nothing."""
    w, b, _ = world_with_body()
    with pytest.raises(ValueError, match="solver"):
        w.solver = value
    with pytest.raises(ValueError, match="kind"):
        b.kind = value
    with pytest.raises(ValueError, match="kind"):
        w.add_body(physics.Circle(1.0), kind=value)
    for attr in ("integrator", "broadphase", "narrowphase"):
        with pytest.raises(ValueError, match=attr.replace("phase", " ?phase")):
            setattr(w, attr, value)
    assert w.solver == "soft_step" and b.kind == "dynamic"
