"""One public class per joint kind (``physics.RevoluteJoint``, ...), derived from the declaration.

The class statements at the end are the table: each gives a class name, its kind and a
description, nothing more (``__slots__ = ()``: a handle keeps no per-instance dict).  The rest is derived when the class is defined
(``_KindJoint.__init_subclass__``): the kind's parameter properties from
``joint_params.PARAMS`` (each Param's doc becomes the property's docstring), its readouts from
``joint_readouts.KINDS``, and a list of its parameters, defaults and units appended to the
class docstring for ``help()``.  They are class statements, not made by ``type()`` in a loop,
so that static readers (the API reference's griffe walk, editors, type checkers) see each name.

Every handle the world makes (``World.add_joint``, scene loading, ``world.joints``,
``world.joint(name)``) is an instance of its kind's class.  Calling a class is the same call as
``add_joint`` on body_a's world (a Body knows its world; the world is never guessed):
``physics.RevoluteJoint(a, b, anchor=(0, 1))`` is ``a.world.add_joint("revolute", a, b, anchor=(0, 1))``
and returns the handle, with the same TypeError and ValueError for bad keywords and values.
"""
from __future__ import annotations

import inspect

from . import joint_params as jp
from .body import Body
from .joint import Joint, _param_property
from .joint_readouts import KINDS as READOUT_KINDS
from .joint_readouts import Readouts
from .store.joints import JOINT_KINDS

#: the class of each kind's handles
CLASS_OF: dict = {}


def _parameter_doc(kind: str) -> str:
    """The part of a kind's class docstring generated from the declaration."""
    params = jp.PARAMS[kind]
    width = max(len(n) for n in params) + 2
    rows = [f"    {n:<{width}}default {p.default!r}: {p.doc}" for n, p in params.items()]
    geometry = ", ".join(jp.GEOMETRY[kind]) or "none"
    readouts = ", ".join(n for n, kinds in READOUT_KINDS.items() if kind in kinds) or "none"
    return "\n".join([
        f'Parameters: keywords of the constructor and of ``World.add_joint("{kind}", ...)``, and',
        "properties of the handle, assignable live (validated; ValueError names the field):",
        "", *rows, "",
        f"Geometry, given at creation only: {geometry}.",
        f"Common to every kind: {', '.join(jp.COMMON)}.",
        f"Readouts: {readouts}.",
    ])


class _KindJoint(Joint):
    """What the kinds' classes share: the constructor and the derivation from the declaration."""

    __slots__ = ()
    _KIND: str = ""

    def __init_subclass__(cls, kind: str, **kw):
        super().__init_subclass__(**kw)
        if kind not in JOINT_KINDS or kind in CLASS_OF:
            raise ValueError(f"kind: expected a joint kind without a class, one of {list(JOINT_KINDS)}, got {kind!r}")
        cls._KIND = kind
        mine = {n for n, kinds in READOUT_KINDS.items() if kind in kinds}
        for name in mine:
            setattr(cls, name, vars(Readouts)[name])
        for name, p in jp.PARAMS[kind].items():
            if name not in mine:  # a distance joint's length reads the distance now (a readout)
                setattr(cls, name, _param_property(name, f"{p.doc} (default {p.default!r})"))
        cls.__doc__ = inspect.cleandoc(cls.__doc__ or "") + "\n\n" + _parameter_doc(kind)
        CLASS_OF[kind] = cls

    def __new__(cls, body_a, body_b=None, **parameters):
        if not isinstance(body_a, Body):
            raise ValueError(f"body_a: expected a live body (its world gets the joint), got {body_a!r}")
        return body_a.world._add_joint(cls._KIND, body_a, body_b, parameters, cls.__name__)

    def __init__(self, body_a, body_b=None, **parameters):
        # __new__ returned the handle the world made, already set up
        pass

    @classmethod
    def _handle(cls, world, oid: int, body_a, body_b):
        """A handle of this class for joint ``oid`` (the world's side: no joint is added)."""
        h = object.__new__(cls)
        Joint.__init__(h, world, oid, cls._KIND, body_a, body_b)
        return h


class RevoluteJoint(_KindJoint, kind="revolute"):
    """A hinge: body_a and body_b share one point (``anchor``) and turn about it freely, or within
    angle limits, driven by a motor or pulled back by a rotational spring.

    body_b None holds body_a to the world.  Calling the class adds the joint to body_a's world
    and returns its handle, as ``world.add_joint("revolute", body_a, body_b, ...)`` does:

    >>> import physics
    >>> world = physics.World()
    >>> door = world.add_body(physics.Polygon.box(0.1, 2.0), position=(0.0, 1.0))
    >>> hinge = physics.RevoluteJoint(door, None, anchor=(0.0, 2.0), lower_angle=-1.5, upper_angle=1.5)
    >>> isinstance(hinge, physics.Joint), hinge.kind, hinge.lower_angle
    (True, 'revolute', -1.5)
    >>> world.joints == [hinge]
    True
    """

    __slots__ = ()


class PrismaticJoint(_KindJoint, kind="prismatic"):
    """A slider: body_a moves along an axis fixed in it relative to body_b, without turning;
    limits, a motor and a spring act along the axis (``axis``, in world coordinates at creation).

    Same as ``world.add_joint("prismatic", body_a, body_b, ...)`` on body_a's world.
    """

    __slots__ = ()


class WeldJoint(_KindJoint, kind="weld"):
    """Glues body_a to body_b at ``anchor``, keeping their relative position and angle: rigid,
    or soft when given a linear or angular frequency.

    Same as ``world.add_joint("weld", body_a, body_b, ...)`` on body_a's world.
    """

    __slots__ = ()


class DistanceJoint(_KindJoint, kind="distance"):
    """Holds an anchor on each body (``anchor_a``, ``anchor_b``) at a rest ``length`` apart, or
    between ``min_length`` and ``max_length`` (a rope: ``max_length`` only); a spring makes
    the length elastic.

    Same as ``world.add_joint("distance", body_a, body_b, ...)`` on body_a's world.
    """

    __slots__ = ()


class WheelJoint(_KindJoint, kind="wheel"):
    """A wheel on a suspension: body_b (the wheel) turns freely about its anchor, which slides
    along ``axis`` of body_a (the chassis) on a spring; a motor turns the wheel.

    Same as ``world.add_joint("wheel", body_a, body_b, ...)`` on body_a's world.
    """

    __slots__ = ()


class MotorJoint(_KindJoint, kind="motor"):
    """Drives body_a towards a position and angle relative to body_b (``linear_offset``,
    ``angular_offset``) with a bounded force and torque, with no anchor.

    Same as ``world.add_joint("motor", body_a, body_b, ...)`` on body_a's world.
    """

    __slots__ = ()


class MouseJoint(_KindJoint, kind="mouse"):
    """Pulls a point of body_a towards a world ``target`` with a soft, bounded force (dragging a
    body with the pointer); body_b must be None.

    Same as ``world.add_joint("mouse", body_a, None, ...)`` on body_a's world.
    """

    __slots__ = ()


class RotaryJoint(_KindJoint, kind="rotary"):
    """Acts on the relative angle of body_a and body_b alone and holds no point: an angular spring
    (``spring_hertz``), a motor (``motor_speed``, ``max_motor_torque``) and angle limits
    (``lower_angle``, ``upper_angle``), each optional (pymunk's DampedRotarySpring, SimpleMotor and
    RotaryLimitJoint in one).  With body_b None it acts on body_a's angle in the world.  The
    ``anchor`` only says where the joint is drawn and picked.

    Same as ``world.add_joint("rotary", body_a, body_b, ...)`` on body_a's world.
    """

    __slots__ = ()


assert tuple(CLASS_OF) == JOINT_KINDS  # every kind has a class, in the declaration's order
#: the classes, exported by ``physics`` (a kind's class statement is all it takes)
__all__ = ["RevoluteJoint", "PrismaticJoint", "WeldJoint", "DistanceJoint", "WheelJoint", "MotorJoint",
           "MouseJoint", "RotaryJoint"]
