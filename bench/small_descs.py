"""The small scenes most people build, as bench descriptions (``python -m bench.small_scenes``).

Five scenes of one to ten bodies, built the same way in Stelkropp and pymunk: one 1 m box resting
on static ground; five boxes stacked; a pendulum (one disc on a revolute joint to the world); ten
1 x 0.2 m boxes hanging as a revolute chain; Newton's cradle (five discs with restitution 1 on
distance joints, the first released from 60 degrees).  dt 1/60, gravity -10, sleeping off.
"""
from __future__ import annotations

import math

from .suite.common import body, box, circle, scene

GROUND = body(box(20.0, 0.5), 0.0, -0.5, kind="static", name="ground", friction=0.6)


def box_on_ground():
    return scene("small_box", "one 1 m box resting on static ground",
                 [GROUND, body(box(0.5, 0.5), 0.0, 0.5, name="box", friction=0.6)])


def stack5():
    boxes = [body(box(0.5, 0.5), 0.0, 0.5 + i, name=f"box{i}", friction=0.6) for i in range(5)]
    return scene("small_stack", "five 1 m boxes stacked on static ground", [GROUND] + boxes)


def pendulum():
    joints = [{"kind": "revolute", "name": "pivot", "a": "bob", "b": None, "anchor": [0.0, 0.0]}]
    return scene("small_pendulum", "one disc on a revolute joint to the world, released level",
                 [body(circle(0.25), 1.0, 0.0, name="bob")], joints)


def chain10():
    links = [body(box(0.5, 0.1), 0.5 + i, 0.0, name=f"link{i}") for i in range(10)]
    joints = [{"kind": "revolute", "name": f"hinge{i}", "a": f"link{i}", "b": f"link{i - 1}" if i else None,
               "anchor": [float(i), 0.0]} for i in range(10)]
    return scene("small_chain", "ten 1 x 0.2 m boxes hanging as a revolute chain, released level", links, joints)


def cradle5(length=2.0, radius=0.25, angle=math.radians(60.0)):
    bodies, joints = [], []
    for i in range(5):
        top = (2.0 * radius * i, length)
        x, y = top[0], 0.0
        if i == 0:
            x, y = top[0] - length * math.sin(angle), length - length * math.cos(angle)
        bodies.append(body(circle(radius), x, y, name=f"ball{i}", restitution=1.0, friction=0.0))
        joints.append({"kind": "distance", "name": f"wire{i}", "a": f"ball{i}", "b": None,
                       "local_anchor_a": [0.0, 0.0], "local_anchor_b": list(top), "length": length})
    return scene("small_cradle", "Newton's cradle: five discs (e = 1) on 2 m distance joints, one released "
                 "from 60 degrees", bodies, joints)


SMALL = {"box": box_on_ground, "stack5": stack5, "pendulum": pendulum, "chain10": chain10, "cradle5": cradle5}


def small(which: str) -> dict:
    """The description of small scene ``which`` (a key of SMALL)."""
    return SMALL[which]()
