"""Select tool: click to select (Shift adds) a body, a spring or a joint, drag on empty space to
box-select, drag a dynamic body on the core's mouse joint (release throws it), drag a static or
kinematic body to move it, and the selection's move and rotate handles (``handles.py``)."""
from __future__ import annotations

import numpy as np

from ..commands import SetProperty
from ..picking import body_at
from .base import JOINT, Tool
from .drag_force import drag_force_limit
from .handles import Handles

BAND = (0.65, 0.8, 1.0, 0.8)


class SelectTool(Tool):
    name = "select"
    snaps = False
    help = "click: select (shift: add); drag empty space: box select; drag a body: pull it on a " \
           "mouse joint (static: move it); handles: move / rotate the selection"

    def __init__(self, editor):
        super().__init__(editor)
        self.joint = None          # the mouse joint (kind "mouse") while a dynamic body is dragged
        self.body = None
        self.moving = None         # (body, grab offset, start position) for static/kinematic moves
        self.cursor = None
        self.band = None           # (start, end) world corners of a box selection, while dragging
        self.band_add = False
        self.handles = Handles(editor)

    def press(self, p, button, mods):
        from pyglet.window import key as K
        ed = self.editor
        grip = self.handles.hit(p)
        if grip is not None:
            self.handles.press(p, grip)
            return
        pin = ed.joint_near(p, lines=False)       # a pin lies on a body: it is picked first
        b = body_at(ed.world, p) if pin is None else None
        link = pin or (None if b is not None else (ed.spring_near(p) or ed.joint_near(p)))
        if link is not None:
            ed.select(link, add=bool(mods & K.MOD_SHIFT))
            return
        if b is None:
            if not mods & K.MOD_SHIFT:
                ed.select(None)
            self.band = (np.array(p, dtype=float), np.array(p, dtype=float))
            self.band_add = bool(mods & K.MOD_SHIFT)
            return
        ed.select(b, add=bool(mods & K.MOD_SHIFT))
        self.cursor = np.array(p, dtype=float)
        if b.kind == "dynamic":
            self.start_joint(b, p)
        else:
            self.moving = (b, np.array(b.position) - np.array(p), b.position)

    def start_joint(self, b, p):
        """The core's mouse joint from the grabbed point to the cursor: a soft constraint at
        ``joint_hertz`` with ``joint_damping_ratio`` (its softness scales with the body's mass, so
        every body follows alike), its force capped at some weights of the body, fewer in the
        stiff modes (``drag_force.py``)."""
        opts = self.editor.tool_options
        self.body = b
        self.joint = self.editor.world.add_joint("mouse", b, None, target=tuple(map(float, p)),
                                                 hertz=opts.joint_hertz, damping_ratio=opts.joint_damping_ratio,
                                                 max_force=drag_force_limit(self.editor.world, b))
        self.editor.tool_joints.add(self.joint.id)

    def drag(self, p):
        self.cursor = np.array(p, dtype=float)
        if self.handles.active is not None:
            self.handles.drag(p)
            return
        if self.band is not None:
            self.band = (self.band[0], self.cursor)
            return
        if self.moving is not None:
            b, off, _ = self.moving
            if b.alive:
                b.position = tuple(self.cursor + off)

    def update(self, cursor):
        if self.joint is not None:
            if not (self.joint.alive and self.body.alive):
                self.end_joint()
            elif self.cursor is not None:
                target = tuple(map(float, self.cursor))
                if target != self.joint.target:      # an unchanged target leaves a resting body asleep
                    self.joint.target = target

    def release(self, p):
        if self.handles.active is not None:
            self.handles.release()
            return
        if self.band is not None:
            self.select_band()
            return
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
            self.editor.tool_joints.discard(self.joint.id)
            if self.joint.alive:
                self.editor.world.remove(self.joint)
            self.joint = None
            self.body = None

    def select_band(self):
        """Select the bodies whose centre lies in the band (Shift: add them); a band of a few
        pixels is a click on empty space (the selection was cleared at the press)."""
        (a, b), self.band = self.band, None
        ed = self.editor
        if np.max(np.abs(b - a)) * ed.camera.scale < 4:
            return
        lo, hi = np.minimum(a, b), np.maximum(a, b)
        inside = [x for x in ed.world.bodies
                  if np.all(lo <= x.center_of_mass) and np.all(np.asarray(x.center_of_mass) <= hi)]
        if not self.band_add:
            ed.select(None)
        for x in inside:
            if x not in ed.selection:
                ed.select(x, add=True)

    def cancel(self):
        self.end_joint()
        self.moving = None
        self.band = None
        self.handles.cancel()

    def decorate(self, decor, cursor):
        if self.band is not None:
            a, b = self.band
            c = [a, (b[0], a[1]), b, (a[0], b[1])]
            for i in range(4):
                decor.segments.append((c[i], c[(i + 1) % 4], 1.0, BAND))
        if self.joint is None and self.moving is None:
            self.handles.decorate(decor)
        if self.joint is not None and self.joint.alive:
            pa, pb = self.joint.anchor_a, self.joint.target
            decor.segments.append((pa, pb, 1.5, JOINT))
            decor.points.append((pa, 4.0, JOINT))
            decor.points.append((pb, 3.0, (1, 1, 1, 0.9)))
