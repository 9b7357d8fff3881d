"""Joint handles: every parameter of a joint readable and assignable live, and its readouts.

A handle stores the world, a stable id, the kind and the two bodies; values live
in the joint table (physics/store/joints.py).  ``Joint`` holds what every kind has
(identity, anchors, collide_connected, break thresholds, reactions); each kind's class
(physics/joint_kinds.py: ``RevoluteJoint``, ...) adds that kind's parameters from
physics/joint_params.py and its readouts from physics/joint_readouts.py, so asking a hinge
for ``max_motor_force`` is an AttributeError saying which parameters it has.  Setters
validate (ValueError naming the field) and wake the joined bodies.  ``reaction_force``
(on body_a, N) and ``reaction_torque`` (on body_a about its anchor, N m) are averaged over
the last solver pass.
"""
from __future__ import annotations

import numpy as np

from . import joint_params as jp
from . import joint_readouts
from .store.joints import BROKEN, COLLIDE, DISTANCE
from .validate import finite_vec


def _param_property(name: str, doc: str):
    """The live, validated property of parameter ``name`` (its Param in joint_params.PARAMS)."""
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
    """Handle of one joint in a :class:`~physics.World`, made by ``World.add_joint`` or by calling
    a kind's class (:class:`~physics.RevoluteJoint`, :class:`~physics.PrismaticJoint`,
    :class:`~physics.WeldJoint`, :class:`~physics.DistanceJoint`, :class:`~physics.WheelJoint`,
    :class:`~physics.MotorJoint`, :class:`~physics.MouseJoint`).

    Every handle is an instance of its kind's class, a subclass of this one (``Joint`` itself is
    never called): the members here are those every kind has; the kind's class adds its
    parameters and readouts.
    """

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

    def _no(self, name: str) -> str:
        """Why this kind has no attribute ``name``: the error says what it has instead."""
        if any(name in params for params in jp.PARAMS.values()):
            return (f"a {self._kind} joint has no parameter {name!r}; it has "
                    f"{', '.join(jp.PARAMS[self._kind])}")
        if name in joint_readouts.KINDS:
            return f"a {self._kind} joint has no {name} (only {', '.join(joint_readouts.KINDS[name])} joints do)"
        return f"{type(self).__name__!r} object has no attribute {name!r}"

    def __getattr__(self, name):
        # reached only when the class lacks ``name``: another kind's parameter or a typo
        if name.startswith("_"):
            raise AttributeError(name)
        raise AttributeError(self._no(name))

    def __setattr__(self, name, value):
        # __slots__ would refuse it too, but without saying which parameters the kind has
        if not name.startswith("_") and not hasattr(type(self), name):
            raise AttributeError(self._no(name))
        object.__setattr__(self, name, value)

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

