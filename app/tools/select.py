"""Select tool: click to select (Shift adds), drag a dynamic body on a soft mouse joint (release
throws it), drag a static or kinematic body to move it."""
from __future__ import annotations

import math

import numpy as np

from ..commands import SetProperty
from .base import JOINT, Tool


class SelectTool(Tool):
    name = "select"
    help = "click: select (shift: add), drag a dynamic body: pull it on a soft spring, release to throw; " \
           "drag a static body: move it"

    def __init__(self, editor):
        super().__init__(editor)
        self.joint = None          # the temporary world spring of the mouse joint
        self.body = None
        self.moving = None         # (body, grab offset, start position) for static/kinematic moves
        self.cursor = None

    def press(self, p, button, mods):
        from pyglet.window import key as K
        ed = self.editor
        b = ed.world.query_point(p)
        spring = None if b is not None else ed.spring_near(p)
        if spring is not None:
            ed.select(spring, add=bool(mods & K.MOD_SHIFT))
            return
        if b is None:
            if not mods & K.MOD_SHIFT:
                ed.select(None)
            return
        ed.select(b, add=bool(mods & K.MOD_SHIFT))
        self.cursor = np.array(p, dtype=float)
        if b.kind == "dynamic":
            self.start_joint(b, p)
        else:
            self.moving = (b, np.array(b.position) - np.array(p), b.position)

    def start_joint(self, b, p):
        """A zero-length world spring from the grabbed point to the cursor, tuned to the body's mass
        so it pulls at ``joint_hertz`` with ``joint_damping_ratio`` (k = m w^2, c = 2 m zeta w)."""
        opts = self.editor.tool_options
        w = 2 * math.pi * opts.joint_hertz
        m = max(b.mass, 1e-6)
        self.body = b
        self.joint = self.editor.world.add_spring(b, None, anchor_a=b.world_to_local(p), anchor_b=tuple(p),
                                                  stiffness=m * w * w,
                                                  damping=2 * m * opts.joint_damping_ratio * w,
                                                  rest_length=0.0)
        self.editor.tool_springs.add(self.joint.id)

    def drag(self, p):
        self.cursor = np.array(p, dtype=float)
        if self.moving is not None:
            b, off, _ = self.moving
            if b.alive:
                b.position = tuple(self.cursor + off)

    def update(self, cursor):
        if self.joint is not None:
            if not (self.joint.alive and self.body.alive):
                self.end_joint()
            elif self.cursor is not None:
                self.joint.anchor_b = tuple(self.cursor)

    def release(self, p):
        self.end_joint()
        if self.moving is not None:
            b, off, start = self.moving
            self.moving = None
            if b.alive and tuple(b.position) != tuple(start):
                new = b.position
                self.editor.execute(SetProperty(self.editor, b, "position", new, old=start))

    def end_joint(self):
        """Remove the mouse joint (on release, and before a save so it is never written)."""
        if self.joint is not None:
            if self.joint.alive:
                self.editor.tool_springs.discard(self.joint.id)
                self.editor.world.remove(self.joint)
            self.joint = None
            self.body = None

    def cancel(self):
        self.end_joint()
        self.moving = None

    def decorate(self, decor, cursor):
        if self.joint is not None and self.joint.alive:
            pa, pb = self.joint.endpoints()
            decor.hidden_springs.add(self.joint.id)
            decor.segments.append((pa, pb, 1.5, JOINT))
            decor.points.append((pa, 4.0, JOINT))
            decor.points.append((pb, 3.0, (1, 1, 1, 0.9)))
