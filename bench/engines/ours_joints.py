"""Stelkropp's joint readouts in Box2D v3's layout (``Box2DV3Sim.joint_readouts``), so the sample
figures (``bench/box2d/figures_*.py``) read the same numbers from both engines.

Box2D's body B is Stelkropp's ``a`` and its body A Stelkropp's ``b`` (bench/box2d/joints.py), so a
reaction "on body B" is Stelkropp's reaction on ``a`` and B-relative-to-A angles are ``a``'s
relative to ``b``; the wheel joint is the exception (``a`` is the chassis, Box2D's A), so its
reaction on B is minus Stelkropp's on ``a``.  The separations follow ``b2Joint_GetLinearSeparation`` /
``b2Joint_GetAngularSeparation`` (box2d-v3 src/joint.c): what the joint should hold at zero and
does not (anchor gap, off-axis gap plus limit overshoot, length error of a rigid distance joint).
Springs come first, as Box2D's bench turns them into soft distance joints ahead of the joints.
"""
from __future__ import annotations

import math

import numpy as np

FIELDS = ("force", "torque", "linear_separation", "angular_separation", "value", "rate", "motor", "valid")


def _overshoot(x, lo, hi) -> float:
    """How far ``x`` lies outside [lo, hi] (None: no bound on that side)."""
    if lo is not None and x < lo:
        return lo - x
    if hi is not None and x > hi:
        return x - hi
    return 0.0


def _axis_of_box2d_a(j) -> np.ndarray:
    """The joint axis carried by Box2D's body A (it measures along A's axis): the wheel's ``a``
    (the chassis), else ``b``'s frame turned by the reference angle."""
    if j.kind == "wheel":
        return np.array(j.axis)
    qb = j.body_b.angle if j.body_b is not None else 0.0
    q = qb + j.reference_angle
    ux, uy = j.local_axis
    return np.array([math.cos(q) * ux - math.sin(q) * uy, math.sin(q) * ux + math.cos(q) * uy])


def _linear(j) -> float:
    d = np.subtract(j.anchor_a, j.anchor_b)
    kind = j.kind
    if kind == "revolute":
        return float(np.hypot(*d))
    if kind == "weld":
        return float(np.hypot(*d)) if j.linear_hertz == 0.0 else 0.0
    if kind in ("prismatic", "wheel"):
        u = _axis_of_box2d_a(j)
        perp = abs(float(d @ (-u[1], u[0])))
        over = _overshoot(float(d @ u), j.lower, j.upper)
        return math.hypot(perp, over)
    if kind == "distance":
        length = float(np.hypot(*d))
        if j.spring_hertz > 0.0:
            return _overshoot(length, j.min_length, j.max_length)
        return abs(length - j.rest_length)
    return 0.0  # motor, mouse: nothing rigid to separate


def _angular(j) -> float:
    kind = j.kind
    if kind == "prismatic":
        return j.angle
    if kind == "weld":
        return j.angle if j.angular_hertz == 0.0 else 0.0
    if kind == "revolute":
        return _overshoot(j.angle, j.lower_angle, j.upper_angle)
    return 0.0


def _value_rate_motor(j):
    kind = j.kind
    if kind == "revolute":
        return j.angle, j.speed, j.motor_torque
    if kind == "prismatic":
        return j.translation, j.speed, j.motor_force
    if kind == "wheel":
        return j.translation, j.speed, j.motor_torque
    if kind == "distance":
        return j.length, 0.0, 0.0
    return 0.0, 0.0, 0.0


def joint_row(j) -> list:
    """The 9 numbers of one joint (force x, y, torque, separations, value, rate, motor, valid)."""
    if not j.alive or j.broken:
        return [math.nan] * 8 + [0.0]
    sign = -1.0 if j.kind == "wheel" else 1.0
    fx, fy = j.reaction_force
    return [sign * fx, sign * fy, sign * j.reaction_torque, _linear(j), _angular(j), *_value_rate_motor(j), 1.0]


def spring_row(s) -> list:
    """A spring as Box2D's soft distance joint: nothing rigid to separate; the force on ``a``
    is the spring's along its axis (Hooke plus the damper on the length's rate)."""
    pa, pb = map(np.asarray, s.endpoints())
    d = pa - pb
    length = float(np.hypot(*d))
    n = d / length if length > 0 else np.zeros(2)
    va = np.asarray(s.body_a.velocity_at(pa))
    vb = np.zeros(2) if s.body_b is None else np.asarray(s.body_b.velocity_at(pb))
    pull = s.stiffness * (length - s.rest_length) + s.damping * float((va - vb) @ n)
    return [*(-pull * n), 0.0, 0.0, 0.0, length, 0.0, 0.0, 1.0]


def readouts(world) -> dict:
    """{field: array} per joint slot of ``world`` (springs first, then joints, in creation order)."""
    rows = [spring_row(s) for s in world.springs] + [joint_row(j) for j in world.joints]
    o = np.array(rows, float).reshape(-1, 9)
    return {"force": o[:, 0:2], "torque": o[:, 2], "linear_separation": o[:, 3], "angular_separation": o[:, 4],
            "value": o[:, 5], "rate": o[:, 6], "motor": o[:, 7], "valid": o[:, 8] > 0}
