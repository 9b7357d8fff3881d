"""Joint geometry and readouts that only some kinds have: angle, axis, translation, length, ...

Each property is written once, on ``Readouts``; ``KINDS`` says which kinds have it (from each
kind's ``readouts`` in physics/joint_params.py), and each
kind's class (physics/joint_kinds.py) takes only those, so a hinge has no ``translation`` at
all: ``dir()``, ``help()`` and the reference show what a kind really offers, and asking for
another kind's readout is an AttributeError naming the kinds that have it (physics/joint.py).
Readouts describe the last step; ``motor_torque``/``motor_force`` are averaged over its
solver pass.
"""
from __future__ import annotations

import math

import numpy as np

from .joint_params import KINDS as KIND_DECL
from .store.joints import MOTOR_ROW
from .validate import finite_num, finite_vec

def _having(name: str) -> tuple:
    return tuple(k for k, d in KIND_DECL.items() if name in d.readouts)


def _rot(q, v):
    c, s = math.cos(q), math.sin(q)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


def _separation(j):
    pa = np.array(j.anchor_a)
    pb = np.array(j.anchor_b)
    return pa, pb, pa - pb


def _rel_velocity(j, pa, pb):
    va = np.array(j._a.velocity_at(pa))
    vb = np.zeros(2) if j._b is None else np.array(j._b.velocity_at(pb))
    return va - vb


def _motor(j):
    span = j._world._joints.span
    return float(j._J.impulse[j._s, MOTOR_ROW] / span) if span > 0 else 0.0


class Readouts:
    """The kind-specific properties, to be copied onto the kinds' classes (never instantiated:
    the methods run on a ``Joint`` handle)."""

    __slots__ = ()

    @property
    def reference_angle(self) -> float:
        """Angle of a relative to b at which the joint's angle reads 0 (rad)."""
        return float(self._J.ref[self._s])

    @reference_angle.setter
    def reference_angle(self, value):
        self._J.ref[self._s] = finite_num(value, "reference_angle")
        self._edited()

    @property
    def local_axis(self) -> tuple[float, float]:
        """Unit axis in body_a's frame."""
        v = self._J.axis[self._s]
        return (float(v[0]), float(v[1]))

    @local_axis.setter
    def local_axis(self, value):
        self._world._set_joint_axis(self, finite_vec(value, "local_axis"), local=True)

    @property
    def axis(self) -> tuple[float, float]:
        """Unit axis in world coordinates now; assigning sets it in a's frame."""
        v = _rot(self._a.angle, self.local_axis)
        return (float(v[0]), float(v[1]))

    @axis.setter
    def axis(self, value):
        self._world._set_joint_axis(self, finite_vec(value, "axis"), local=False)

    @property
    def angle(self) -> float:
        """Angle of body_a relative to body_b minus the reference angle (rad)."""
        qb = self._b.angle if self._b is not None else 0.0
        return self._a.angle - qb - float(self._J.ref[self._s])

    @property
    def translation(self) -> float:
        """Position of a's anchor relative to b's along the axis (m)."""
        return float(_separation(self)[2] @ np.array(self.axis))

    @property
    def length(self) -> float:
        """Distance between the anchors now (m).  Assigning sets the rest length."""
        return float(np.hypot(*_separation(self)[2]))

    @length.setter
    def length(self, value):
        self._J.length[self._s] = finite_num(value, "length", lo=0.0)
        self._edited(structural=True)

    @property
    def rest_length(self) -> float:
        """The rest length (m), the ``length`` the joint was given."""
        return float(self._J.length[self._s])

    @property
    def speed(self) -> float:
        """Rate of what the joint's motor drives or its limits bound: rad/s of the relative angle
        for a kind with an angular motor (revolute, wheel), m/s of the length for distance, m/s along
        the axis for prismatic."""
        decl = KIND_DECL[self._kind]
        if decl.motor == "angular":
            wb = self._b.angular_velocity if self._b is not None else 0.0
            return self._a.angular_velocity - wb
        pa, pb, d = _separation(self)
        dv = _rel_velocity(self, pa, pb)
        if decl.coordinate == "length":
            n = np.hypot(*d)
            return float(dv @ d / n) if n > 0 else 0.0
        u = np.array(self.axis)
        w = self._a.angular_velocity
        return float(dv @ u + d @ (w * np.array([-u[1], u[0]])))

    @property
    def motor_torque(self) -> float:
        """Torque (N m) the motor applied in the last step."""
        return _motor(self)

    @property
    def motor_force(self) -> float:
        """Force (N) the motor applied in the last step."""
        return _motor(self)


#: the kinds that have each property of Readouts (in the properties' order)
KINDS = {n: _having(n) for n, v in vars(Readouts).items() if isinstance(v, property)}
assert {r for d in KIND_DECL.values() for r in d.readouts} <= set(KINDS)
