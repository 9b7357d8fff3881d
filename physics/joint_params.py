"""The joint kinds, declared in one place: each kind's parameters, geometry, readouts and
capabilities (``KINDS``), in the order of their codes in the joint table.

One declaration serves ``World.add_joint`` (which keywords a kind takes and
their defaults), the ``Joint`` handle's validated setters and readouts, the
kinds' public classes (physics/joint_kinds.py), the scene format and its schema
(physics/scene/), the energy guard's motor bound, and the sandbox's inspector,
tools and drawing, so a parameter is named and checked in one place.  What a
kind adds besides its entry here: its rows (``constraints/joints/<kind>.py``),
one branch per verb in ``constraints/joints/dispatch.py`` and its class
statement (docs/internals.md, "How to add a joint kind").

Rules: ``num`` any finite number; ``nonneg`` finite and >= 0; ``limit`` a finite
number or None (no limit); ``length`` a length >= 0 or None; ``vec`` a pair of
finite numbers.  Geometry (anchors, axis, reference angle) is given at creation
in world coordinates or as exact body-frame values (``GEOMETRY``).
"""
from __future__ import annotations

import math
from collections import namedtuple

from .validate import finite_num, finite_vec

Param = namedtuple("Param", "field default rule doc")

Kind = namedtuple("Kind", "params geometry readouts coordinate motor equality axis doc")
Kind.__doc__ = """One joint kind's declaration.

- ``params``: {public name: Param}, the keywords of ``add_joint`` and the handle's live properties;
- ``geometry``: the creation-only keywords (world points and axis, or exact body-frame values);
  with ``anchor`` the kind has one anchor point on each body (coinciding at creation), with
  ``anchor_a``/``anchor_b`` two given apart;
- ``readouts``: the properties of physics/joint_readouts.py's ``Readouts`` it has; with
  ``reference_angle`` among them, the angle of a relative to b at creation is its zero;
- ``coordinate``: the readout its limits bound (``angle``, ``translation``, ``length``) or None;
- ``motor``: what its motor row drives, ``angular`` (a torque on the relative angle) or
  ``linear`` (a force along its axis), or None; ``speed`` reads the rate it drives;
- ``equality``: how many equality rows hold it together (a distance joint: when rigid);
- ``axis``: the default axis (world coordinates) of a kind with an axis, else None;
- ``doc``: one line for the sandbox's tool and the docs."""

_SPRING = {
    "spring_hertz": Param("hertz", 0.0, "nonneg", "spring frequency (Hz); 0 = no spring"),
    "spring_damping_ratio": Param("zeta", 0.0, "nonneg", "spring damping ratio (1 = critical)"),
}
_ANGLE_LIMITS = {
    "lower_angle": Param("lower", None, "limit", "lower limit of the angle (rad); None = free"),
    "upper_angle": Param("upper", None, "limit", "upper limit of the angle (rad); None = free"),
}
_ANGULAR_MOTOR = {
    "motor_speed": Param("motor_speed", 0.0, "num", "motor target speed of a relative to b (rad/s)"),
    "max_motor_torque": Param("max_motor", 0.0, "nonneg", "largest motor torque (N m); 0 = motor off"),
}
_LOCAL = ("local_anchor_a", "local_anchor_b")

KINDS = {
    "revolute": Kind(
        params={**_ANGLE_LIMITS, **_ANGULAR_MOTOR, **_SPRING},
        geometry=("anchor", *_LOCAL, "reference_angle"),
        readouts=("reference_angle", "angle", "speed", "motor_torque"),
        coordinate="angle", motor="angular", equality=2, axis=None,
        doc="a shared point the bodies turn about (a hinge)"),
    "prismatic": Kind(
        params={
            "lower": Param("lower", None, "limit", "lower limit of the translation (m); None = free"),
            "upper": Param("upper", None, "limit", "upper limit of the translation (m); None = free"),
            "motor_speed": Param("motor_speed", 0.0, "num", "motor target speed along the axis (m/s)"),
            "max_motor_force": Param("max_motor", 0.0, "nonneg", "largest motor force (N); 0 = motor off"),
            **_SPRING,
        },
        geometry=("anchor", "axis", *_LOCAL, "local_axis", "reference_angle"),
        readouts=("reference_angle", "local_axis", "axis", "angle", "translation", "speed", "motor_force"),
        coordinate="translation", motor="linear", equality=2, axis=(1.0, 0.0),
        doc="a slide along an axis of body_a, with no turning"),
    "weld": Kind(
        params={
            "linear_hertz": Param("hertz", 0.0, "nonneg", "stiffness of the point as a frequency (Hz); 0 = rigid"),
            "angular_hertz": Param("hertz2", 0.0, "nonneg", "stiffness of the angle as a frequency (Hz); 0 = rigid"),
            "damping_ratio": Param("zeta", 0.0, "nonneg", "damping ratio of a soft weld"),
        },
        geometry=("anchor", *_LOCAL, "reference_angle"),
        readouts=("reference_angle", "angle"),
        coordinate="angle", motor=None, equality=3, axis=None,
        doc="the bodies held together at a point and angle (rigid, or soft)"),
    "distance": Kind(
        params={
            "length": Param("length", None, "length", "rest length (m); None = the distance at creation"),
            "min_length": Param("lower", None, "length", "shortest allowed length (m); None = no limit"),
            "max_length": Param("upper", None, "length", "longest allowed length (m); None = no limit (a rope: "
                                                         "max_length only)"),
            **_SPRING,
        },
        geometry=("anchor_a", "anchor_b", *_LOCAL),
        readouts=("length", "rest_length", "speed"),
        coordinate="length", motor=None, equality=1, axis=None,
        doc="a rod, spring or rope between two anchor points"),
    "wheel": Kind(
        params={
            "spring_hertz": Param("hertz", 4.0, "nonneg", "suspension frequency (Hz); 0 = no spring"),
            "spring_damping_ratio": Param("zeta", 0.7, "nonneg", "suspension damping ratio"),
            **_ANGULAR_MOTOR,
            "lower": Param("lower", None, "limit", "lower limit of the suspension travel (m); None = free"),
            "upper": Param("upper", None, "limit", "upper limit of the suspension travel (m); None = free"),
        },
        geometry=("anchor", "axis", *_LOCAL, "local_axis"),
        readouts=("reference_angle", "local_axis", "axis", "angle", "translation", "speed", "motor_torque"),
        coordinate="translation", motor="angular", equality=1, axis=(0.0, 1.0),
        doc="body_b turns freely on a sprung axle sliding along an axis of body_a"),
    "motor": Kind(
        params={
            "linear_offset": Param("offset", (0.0, 0.0), "vec", "target position of a's origin in b's body "
                                                                "coordinates (m)"),
            "angular_offset": Param("ref", 0.0, "num", "target angle of a relative to b (rad)"),
            "max_force": Param("max_motor", 100.0, "nonneg", "largest force (N)"),
            "max_torque": Param("max_torque", 100.0, "nonneg", "largest torque (N m)"),
        },
        geometry=(),
        readouts=("angle",),
        coordinate="angle", motor=None, equality=0, axis=None,
        doc="drives body_a towards an offset and angle relative to body_b, with bounded force"),
    "mouse": Kind(
        params={
            "target": Param("lb", None, "vec", "world point the grabbed point is pulled to (m)"),
            "hertz": Param("hertz", 5.0, "nonneg", "stiffness as a frequency (Hz)"),
            "damping_ratio": Param("zeta", 0.7, "nonneg", "damping ratio"),
            "max_force": Param("max_motor", 1000.0, "nonneg", "largest force (N)"),
        },
        geometry=("local_anchor_a",),
        readouts=(),
        coordinate=None, motor=None, equality=0, axis=None,
        doc="pulls a point of body_a towards a world target (a drag)"),
    "rotary": Kind(
        params={**_ANGLE_LIMITS, **_ANGULAR_MOTOR, **_SPRING},
        geometry=("anchor", *_LOCAL, "reference_angle"),
        readouts=("reference_angle", "angle", "speed", "motor_torque"),
        coordinate="angle", motor="angular", equality=0, axis=None,
        doc="the relative angle only: an angular spring, a motor and angle limits"),
}

#: the kinds in code order (``J.kind`` holds the index)
JOINT_KINDS = tuple(KINDS)
#: parameters per kind
PARAMS = {k: d.params for k, d in KINDS.items()}
#: creation-only geometry per kind (world coordinates, or the exact body-frame values)
GEOMETRY = {k: d.geometry for k, d in KINDS.items()}
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
