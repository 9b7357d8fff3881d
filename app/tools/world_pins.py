"""A body held to the world by a pin-like joint (hinge, weld, slider, wheel, motor) moved or turned
with the handles takes the joint's world point along: left behind, the joint would pull the body
back to it as soon as the scene plays.  Ropes, distance joints and springs keep their world
point (moving the body stretches them, which is an edit of its own)."""
from __future__ import annotations

import numpy as np

from ..commands import SetProperty

STRETCHY = ("distance", "mouse")


def pin_commands(editor, bodies, move):
    """SetProperty commands giving the world point of each user joint from one of ``bodies`` to
    the world the rigid ``move`` (a function of a world point) the bodies made."""
    ids = {b.id for b in bodies}
    cmds = []
    for j in editor.world.joints:
        if j.body_b is not None or j.body_a.id not in ids or j.kind in STRETCHY or editor.is_tool_joint(j):
            continue
        old = tuple(map(float, j.anchor_b))
        new = tuple(map(float, move(np.array(old))))
        if new != old:
            cmds.append(SetProperty(editor, j, "anchor_b", new, old=old))
    return cmds
