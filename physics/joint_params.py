"""The joints' parameters by kind: public name, table field, default and rule (issue 14's API).

One declaration serves ``World.add_joint`` (which keywords a kind takes and
their defaults), the ``Joint`` handle's validated setters and the scene format
(physics/scene/), so a parameter is named and checked in one place.

Rules: ``num`` any finite number; ``nonneg`` finite and >= 0; ``limit`` a finite
number or None (no limit); ``length`` a length >= 0 or None; ``vec`` a pair of
finite numbers.  Geometry (anchors, axis, reference angle) is given at creation
in world coordinates or as exact body-frame values (``GEOMETRY``).
"""
from __future__ import annotations

import math
from collections import namedtuple

from .store.joints import JOINT_KINDS
from .validate import finite_num, finite_vec

Param = namedtuple("Param", "field default rule doc")

_SPRING = {
    "spring_hertz": Param("hertz", 0.0, "nonneg", "spring frequency (Hz); 0 = no spring"),
    "spring_damping_ratio": Param("zeta", 0.0, "nonneg", "spring damping ratio (1 = critical)"),
}

PARAMS = {
    "revolute": {
        "lower_angle": Param("lower", None, "limit", "lower limit of the angle (rad); None = free"),
        "upper_angle": Param("upper", None, "limit", "upper limit of the angle (rad); None = free"),
        "motor_speed": Param("motor_speed", 0.0, "num", "motor target speed of a relative to b (rad/s)"),
        "max_motor_torque": Param("max_motor", 0.0, "nonneg", "largest motor torque (N m); 0 = motor off"),
        **_SPRING,
    },
    "prismatic": {
        "lower": Param("lower", None, "limit", "lower limit of the translation (m); None = free"),
        "upper": Param("upper", None, "limit", "upper limit of the translation (m); None = free"),
        "motor_speed": Param("motor_speed", 0.0, "num", "motor target speed along the axis (m/s)"),
        "max_motor_force": Param("max_motor", 0.0, "nonneg", "largest motor force (N); 0 = motor off"),
        **_SPRING,
    },
    "weld": {
        "linear_hertz": Param("hertz", 0.0, "nonneg", "stiffness of the point as a frequency (Hz); 0 = rigid"),
        "angular_hertz": Param("hertz2", 0.0, "nonneg", "stiffness of the angle as a frequency (Hz); 0 = rigid"),
        "damping_ratio": Param("zeta", 0.0, "nonneg", "damping ratio of a soft weld"),
    },
    "distance": {
        "length": Param("length", None, "length", "rest length (m); None = the distance at creation"),
        "min_length": Param("lower", None, "length", "shortest allowed length (m); None = no limit"),
        "max_length": Param("upper", None, "length", "longest allowed length (m); None = no limit (a rope: "
                                                     "max_length only)"),
        **_SPRING,
    },
    "wheel": {
        "spring_hertz": Param("hertz", 4.0, "nonneg", "suspension frequency (Hz); 0 = no spring"),
        "spring_damping_ratio": Param("zeta", 0.7, "nonneg", "suspension damping ratio"),
        "motor_speed": Param("motor_speed", 0.0, "num", "motor target speed of a relative to b (rad/s)"),
        "max_motor_torque": Param("max_motor", 0.0, "nonneg", "largest motor torque (N m); 0 = motor off"),
        "lower": Param("lower", None, "limit", "lower limit of the suspension travel (m); None = free"),
        "upper": Param("upper", None, "limit", "upper limit of the suspension travel (m); None = free"),
    },
    "motor": {
        "linear_offset": Param("offset", (0.0, 0.0), "vec", "target position of a's origin in b's body "
                                                            "coordinates (m)"),
        "angular_offset": Param("ref", 0.0, "num", "target angle of a relative to b (rad)"),
        "max_force": Param("max_motor", 100.0, "nonneg", "largest force (N)"),
        "max_torque": Param("max_torque", 100.0, "nonneg", "largest torque (N m)"),
    },
    "mouse": {
        "target": Param("lb", None, "vec", "world point the grabbed point is pulled to (m)"),
        "hertz": Param("hertz", 5.0, "nonneg", "stiffness as a frequency (Hz)"),
        "damping_ratio": Param("zeta", 0.7, "nonneg", "damping ratio"),
        "max_force": Param("max_motor", 1000.0, "nonneg", "largest force (N)"),
    },
}
assert tuple(PARAMS) == JOINT_KINDS

#: creation-only geometry per kind (world coordinates, or the exact body-frame values)
GEOMETRY = {
    "revolute": ("anchor", "local_anchor_a", "local_anchor_b", "reference_angle"),
    "prismatic": ("anchor", "axis", "local_anchor_a", "local_anchor_b", "local_axis", "reference_angle"),
    "weld": ("anchor", "local_anchor_a", "local_anchor_b", "reference_angle"),
    "distance": ("anchor_a", "anchor_b", "local_anchor_a", "local_anchor_b"),
    "wheel": ("anchor", "axis", "local_anchor_a", "local_anchor_b", "local_axis"),
    "motor": (),
    "mouse": ("local_anchor_a",),
}
COMMON = ("name", "collide_connected", "break_force", "break_torque")
#: the limit pairs that must stay ordered (lower <= upper)
PAIRS = {"lower_angle": "upper_angle", "lower": "upper", "min_length": "max_length"}


def check(name: str, rule: str, value):
    """The validated value of parameter ``name`` (None for an unset optional); ValueError names it."""
    if rule == "vec":
        return finite_vec(value, name)
    if rule in ("limit", "length") and value is None:
        return None
    lo = 0.0 if rule in ("nonneg", "length") else None
    return finite_num(value, name, lo=lo)


def breaking(name: str, value):
    """A break threshold: None (unbreakable) or a number > 0."""
    if value is None:
        return None
    return finite_num(value, name, lo=0.0, lo_open=True)


def ordered(kind: str, values: dict) -> None:
    """ValueError naming the upper parameter if a limit pair is reversed."""
    for lo, hi in PAIRS.items():
        if lo in PARAMS[kind]:
            a, b = values.get(lo), values.get(hi)
            if a is not None and b is not None and a > b:
                raise ValueError(f"{hi}: must be >= {lo} ({a!r}), got {b!r}")


def unset(x: float):
    """None for a stored NaN (an unset optional parameter), else the float."""
    return None if math.isnan(x) else float(x)
