"""Box tool: drag out an axis-aligned box (a click: a box of the palette's default size)."""
from __future__ import annotations

import numpy as np

import physics

from ..commands import AddBody
from .base import PREVIEW, Tool, body_args


class BoxTool(Tool):
    name = "box"
    help = "drag: draw a box (click: a default box)"
    droppable = True

    def __init__(self, editor):
        super().__init__(editor)
        self.start = None
        self.end = None

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
        size = np.abs(b - a)
        opts = self.editor.tool_options
        if np.max(size) * self.editor.camera.scale < 6:   # a click: default size
            size = np.array([opts.default_size, opts.default_size])
            centre = a
        else:
            size = np.maximum(size, 0.05)
            centre = 0.5 * (a + b)
        self.editor.create(AddBody({"shape": physics.Polygon.box(*size), **body_args(opts, centre)},
                                   "create box"))

    def drop(self, p):
        o = self.editor.tool_options
        self.editor.create(AddBody({"shape": physics.Polygon.box(o.default_size, o.default_size),
                                    **body_args(o, p)}, "drop box"))

    def cancel(self):
        self.start = self.end = None

    def decorate(self, decor, cursor):
        if self.start is not None:
            a, b = self.start, self.end
            c = [a, (b[0], a[1]), b, (a[0], b[1])]
            for i in range(4):
                decor.segments.append((c[i], c[(i + 1) % 4], 1.5, PREVIEW))
