"""Capsule tool: drag from one end centre to the other (the palette's capsule radius); a click
makes a level capsule of the default size."""
from __future__ import annotations

import numpy as np

import physics

from ..commands import AddBody
from .base import PREVIEW, Tool, body_args


def capsule_about_middle(a, b, radius):
    """(capsule centred on the body origin, the origin = the middle of a-b, angle)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    half = 0.5 * np.hypot(*(b - a))
    angle = float(np.arctan2(*(b - a)[::-1]))
    return physics.Capsule((-half, 0.0), (half, 0.0), radius), 0.5 * (a + b), angle


class CapsuleTool(Tool):
    name = "capsule"
    help = "drag from one end to the other: a capsule (radius in the palette); click: a default one"
    droppable = True

    def __init__(self, editor):
        super().__init__(editor)
        self.start = self.end = None

    def press(self, p, button, mods):
        self.start = self.end = np.array(p, dtype=float)

    def drag(self, p):
        if self.start is not None:
            self.end = np.array(p, dtype=float)

    def release(self, p):
        if self.start is None:
            return
        a, b = self.start, np.array(p, dtype=float)
        self.start = self.end = None
        if np.hypot(*(b - a)) * self.editor.camera.scale < 6:     # a click: default size, level
            self.drop(a)
            return
        o = self.editor.tool_options
        shape, centre, angle = capsule_about_middle(a, b, o.capsule_radius)
        self.editor.create(AddBody({"shape": shape, **body_args(o, centre, angle)}, "create capsule"))

    def drop(self, p):
        o = self.editor.tool_options
        half = 0.5 * o.default_size
        shape = physics.Capsule((-half, 0.0), (half, 0.0), o.capsule_radius)
        self.editor.create(AddBody({"shape": shape, **body_args(o, p)}, "create capsule"))

    def cancel(self):
        self.start = self.end = None

    def decorate(self, decor, cursor):
        if self.start is None:
            return
        a, b = self.start, self.end
        d = b - a
        ln = np.hypot(*d)
        r = self.editor.tool_options.capsule_radius
        n = np.array([-d[1], d[0]]) / ln * r if ln > 0 else np.zeros(2)
        decor.segments += [(a + n, b + n, 1.5, PREVIEW), (a - n, b - n, 1.5, PREVIEW)]
        decor.points += [(a, 4.0, PREVIEW), (b, 4.0, PREVIEW)]
