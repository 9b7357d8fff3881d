"""Joint handles: every parameter of a joint readable and assignable live, and its readouts.

A handle stores the world, a stable id, the kind and the two bodies; values live
in the joint table (physics/store/joints.py).  Parameters are those of
physics/joint_params.py for the joint's kind (asking a hinge for ``max_motor_force``
is an AttributeError); setters validate (ValueError naming the field) and wake the
joined bodies.  Readouts describe the last step: ``angle``, ``translation``,
``length`` and ``speed`` now; ``motor_torque``/``motor_force``, ``reaction_force``
(on body_a, N) and ``reaction_torque`` (on body_a about its anchor, N m) averaged
over the last solver pass.
"""
from __future__ import annotations

import math

import numpy as np

from . import joint_params as jp
from .store.joints import BROKEN, COLLIDE, DISTANCE, MOTOR_ROW
from .validate import finite_num, finite_vec


def _rot(q, v):
    c, s = math.cos(q), math.sin(q)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


def _param_property(name: str, doc: str):
    def get(self):
        p = self._spec(name)
        arr = getattr(self._J, p.field)
        v = arr[self._s]
        if p.rule == "vec":
            return (float(v[0]), float(v[1]))
        return jp.unset(v) if p.rule in ("limit", "length") else float(v)

    def put(self, value):
        p = self._spec(name)
        v = jp.check(name, p.rule, value)
        for lo, hi in jp.PAIRS.items():
            if name in (lo, hi) and lo in jp.PARAMS[self._kind]:
                jp.ordered(self._kind, {lo: getattr(self, lo), hi: getattr(self, hi), name: v})
        if name == "target" or name == "linear_offset":
            self._world._set_joint_point(self, name, v)
        else:
            getattr(self._J, p.field)[self._s] = np.nan if v is None else v
        self._edited(structural=self._J.kind[self._s] == DISTANCE)
    return property(get, put, doc=doc)


class Joint:
    """Handle of one joint in a :class:`~physics.World` (``World.add_joint``)."""

    __slots__ = ("_world", "_id", "_kind", "_a", "_b")

    def __init__(self, world, oid: int, kind: str, body_a, body_b):
        self._world = world
        self._id = oid
        self._kind = kind
        self._a = body_a
        self._b = body_b

    # -- identity ------------------------------------------------------------
    @property
    def kind(self) -> str:
        """One of revolute, prismatic, weld, distance, wheel, motor, mouse (read-only)."""
        return self._kind

    @property
    def body_a(self):
        """The first body (angles and speeds are its, relative to body_b)."""
        return self._a

    @property
    def body_b(self):
        """The second body, or None when the joint holds body_a to the world."""
        return self._b

    @property
    def id(self) -> int:
        """Stable id of the joint in its world."""
        return self._id

    @property
    def alive(self) -> bool:
        """False once removed from its world (a broken joint is still alive: see ``broken``)."""
        return self._id in self._world._joints.slot_of

    @property
    def name(self):
        """Unique name in the world, or None."""
        return self._world._joint_names.name_of(self._id)

    @name.setter
    def name(self, value):
        self._world._joint_names.rename(self._id, value)

    # -- plumbing ------------------------------------------------------------
    @property
    def _s(self) -> int:
        try:
            return self._world._joints.slot_of[self._id]
        except KeyError:
            raise ValueError(f"joint {self._id} was removed from its world") from None

    @property
    def _J(self):
        return self._world._joints.view

    def _spec(self, name):
        spec = jp.PARAMS[self._kind].get(name)
        if spec is None:
            raise AttributeError(f"a {self._kind} joint has no parameter {name!r}; it has "
                                 f"{', '.join(jp.PARAMS[self._kind])}")
        return spec

    def _need(self, what, kinds):
        if self._kind not in kinds:
            raise AttributeError(f"a {self._kind} joint has no {what}")

    def _edited(self, structural=False):
        self._world._joint_edited(self, structural)

    # -- common parameters ---------------------------------------------------
    @property
    def collide_connected(self) -> bool:
        """Whether the two joined bodies still collide with each other."""
        return bool(self._J.flags[self._s] & COLLIDE)

    @collide_connected.setter
    def collide_connected(self, value):
        if not isinstance(value, (bool, np.bool_)):
            raise ValueError(f"collide_connected: must be true or false, got {value!r}")
        s = self._s
        self._J.flags[s] = (self._J.flags[s] | COLLIDE) if value else (self._J.flags[s] & ~COLLIDE)
        self._edited(structural=True)

    @property
    def break_force(self):
        """Reaction force (N) at which the joint breaks; None = unbreakable."""
        return jp.unset(self._J.break_force[self._s])

    @break_force.setter
    def break_force(self, value):
        v = jp.breaking("break_force", value)
        self._J.break_force[self._s] = np.nan if v is None else v
        self._edited()

    @property
    def break_torque(self):
        """Reaction torque (N m) at which the joint breaks; None = unbreakable."""
        return jp.unset(self._J.break_torque[self._s])

    @break_torque.setter
    def break_torque(self, value):
        v = jp.breaking("break_torque", value)
        self._J.break_torque[self._s] = np.nan if v is None else v
        self._edited()

    @property
    def broken(self) -> bool:
        """True once the reaction exceeded break_force or break_torque (the joint then holds nothing)."""
        return bool(self._J.flags[self._s] & BROKEN)

    # -- geometry --------------------------------------------------------------
    def _local(self, side):
        body = self._a if side == "a" else self._b
        v = (self._J.la if side == "a" else self._J.lb)[self._s]
        if body is None:
            return np.array(v)
        return v + body._B.com[body._s]

    @property
    def local_anchor_a(self) -> tuple[float, float]:
        """The anchor on body_a in its body coordinates (m)."""
        v = self._local("a")
        return (float(v[0]), float(v[1]))

    @property
    def local_anchor_b(self) -> tuple[float, float]:
        """The anchor on body_b in its body coordinates, or the world point when body_b is None."""
        v = self._local("b")
        return (float(v[0]), float(v[1]))

    def _world_anchor(self, side):
        body = self._a if side == "a" else self._b
        if body is None:
            return self.local_anchor_b
        return body.local_to_world(self._local(side))

    @property
    def anchor_a(self) -> tuple[float, float]:
        """World position of the anchor on body_a now."""
        return self._world_anchor("a")

    @anchor_a.setter
    def anchor_a(self, value):
        self._world._set_joint_anchor(self, "a", finite_vec(value, "anchor_a"))

    @property
    def anchor_b(self) -> tuple[float, float]:
        """World position of the anchor on body_b now (the world point when body_b is None)."""
        return self._world_anchor("b")

    @anchor_b.setter
    def anchor_b(self, value):
        self._world._set_joint_anchor(self, "b", finite_vec(value, "anchor_b"))

    @property
    def anchor(self) -> tuple[float, float]:
        """World position of the joint (body_a's anchor); assigning re-anchors both bodies there."""
        return self.anchor_a

    @anchor.setter
    def anchor(self, value):
        v = finite_vec(value, "anchor")
        self._world._set_joint_anchor(self, "a", v)
        if self._kind != "mouse":
            self._world._set_joint_anchor(self, "b", v)

    @property
    def reference_angle(self) -> float:
        """Angle of a relative to b at which the joint's angle reads 0 (rad)."""
        self._need("reference angle", ("revolute", "prismatic", "weld", "wheel"))
        return float(self._J.ref[self._s])

    @reference_angle.setter
    def reference_angle(self, value):
        self._need("reference angle", ("revolute", "prismatic", "weld", "wheel"))
        self._J.ref[self._s] = finite_num(value, "reference_angle")
        self._edited()

    @property
    def local_axis(self) -> tuple[float, float]:
        """Unit axis in body_a's frame (prismatic, wheel)."""
        self._need("axis", ("prismatic", "wheel"))
        v = self._J.axis[self._s]
        return (float(v[0]), float(v[1]))

    @local_axis.setter
    def local_axis(self, value):
        self._need("axis", ("prismatic", "wheel"))
        self._world._set_joint_axis(self, finite_vec(value, "local_axis"), local=True)

    @property
    def axis(self) -> tuple[float, float]:
        """Unit axis in world coordinates now (prismatic, wheel); assigning sets it in a's frame."""
        v = _rot(self._a.angle, self.local_axis)
        return (float(v[0]), float(v[1]))

    @axis.setter
    def axis(self, value):
        self._need("axis", ("prismatic", "wheel"))
        self._world._set_joint_axis(self, finite_vec(value, "axis"), local=False)

    # -- readouts ----------------------------------------------------------------
    @property
    def angle(self) -> float:
        """Angle of body_a relative to body_b minus the reference angle (rad)."""
        self._need("angle", ("revolute", "weld", "wheel", "prismatic", "motor"))
        qb = self._b.angle if self._b is not None else 0.0
        return self._a.angle - qb - float(self._J.ref[self._s])

    def _separation(self):
        pa = np.array(self.anchor_a)
        pb = np.array(self.anchor_b)
        return pa, pb, pa - pb

    def _rel_velocity(self, pa, pb):
        va = np.array(self._a.velocity_at(pa))
        vb = np.zeros(2) if self._b is None else np.array(self._b.velocity_at(pb))
        return va - vb

    @property
    def translation(self) -> float:
        """Position of a's anchor relative to b's along the axis (m; prismatic, wheel)."""
        self._need("translation", ("prismatic", "wheel"))
        return float(self._separation()[2] @ np.array(self.axis))

    @property
    def length(self) -> float:
        """Distance between the anchors now (m; distance joint).  Assigning sets the rest length."""
        self._need("length", ("distance",))
        return float(np.hypot(*self._separation()[2]))

    @length.setter
    def length(self, value):
        self._need("length", ("distance",))
        self._J.length[self._s] = finite_num(value, "length", lo=0.0)
        self._edited(structural=True)

    @property
    def rest_length(self) -> float:
        """The distance joint's rest length (m), the ``length`` it was given."""
        self._need("rest length", ("distance",))
        return float(self._J.length[self._s])

    @property
    def speed(self) -> float:
        """Rate of the joint's coordinate: rad/s for revolute and wheel (the motor's speed), m/s along
        the axis for prismatic, m/s of the length for distance."""
        self._need("speed", ("revolute", "wheel", "prismatic", "distance"))
        if self._kind in ("revolute", "wheel"):
            wb = self._b.angular_velocity if self._b is not None else 0.0
            return self._a.angular_velocity - wb
        pa, pb, d = self._separation()
        dv = self._rel_velocity(pa, pb)
        if self._kind == "distance":
            n = np.hypot(*d)
            return float(dv @ d / n) if n > 0 else 0.0
        u = np.array(self.axis)
        w = self._a.angular_velocity
        return float(dv @ u + d @ (w * np.array([-u[1], u[0]])))

    def _motor(self):
        span = self._world._joints.span
        return float(self._J.impulse[self._s, MOTOR_ROW] / span) if span > 0 else 0.0

    @property
    def motor_torque(self) -> float:
        """Torque (N m) the motor applied in the last step (revolute, wheel)."""
        self._need("motor torque", ("revolute", "wheel"))
        return self._motor()

    @property
    def motor_force(self) -> float:
        """Force (N) the motor applied in the last step (prismatic)."""
        self._need("motor force", ("prismatic",))
        return self._motor()

    @property
    def reaction_force(self) -> tuple[float, float]:
        """Force (N) the joint applied to body_a in the last step."""
        f = self._J.force[self._s]
        return (float(f[0]), float(f[1]))

    @property
    def reaction_torque(self) -> float:
        """Torque (N m) the joint applied to body_a about its anchor in the last step."""
        return float(self._J.torque[self._s])

    def __repr__(self):
        if not self.alive:
            return f"<Joint {self._id} (removed)>"
        b = self._b.name if self._b is not None else "world"
        return f"<Joint {self.name or self._id} {self._kind}: {self._a.name} - {b}>"


for _name in sorted({n for params in jp.PARAMS.values() for n in params} - {"length"}):
    _doc = next(p.doc for params in jp.PARAMS.values() for n, p in params.items() if n == _name)
    setattr(Joint, _name, _param_property(_name, _doc))
del _name, _doc
