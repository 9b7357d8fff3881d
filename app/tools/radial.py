"""Tools that press at a centre and drag out a radius (circle, regular polygon)."""
from __future__ import annotations

import numpy as np

from ..commands import AddBody
from .base import PREVIEW, PREVIEW_DIM, Tool, body_args


class RadialTool(Tool):
    """Press at the centre, drag out the radius (click: default size).  Subclasses give
    ``shape(r)`` (r in metres) and, if the preview is not a circle, ``outline(r)``."""

    droppable = True

    def __init__(self, editor):
        super().__init__(editor)
        self.centre = None
        self.radius = 0.0

    def shape(self, r):
        raise NotImplementedError

    def press(self, p, button, mods):
        self.centre = np.array(p, dtype=float)
        self.radius = 0.0

    def drag(self, p):
        if self.centre is not None:
            self.radius = float(np.hypot(*(np.array(p) - self.centre)))

    def release(self, p):
        if self.centre is None:
            return
        c, r = self.centre, self.radius
        self.centre = None
        if r * self.editor.camera.scale < 6:
            r = 0.5 * self.editor.tool_options.default_size
        r = max(r, 0.03)
        self.editor.create(AddBody({"shape": self.shape(r), **body_args(self.editor.tool_options, c)},
                                   f"create {self.name}"))

    def drop(self, p):
        o = self.editor.tool_options
        self.editor.create(AddBody({"shape": self.shape(0.5 * o.default_size), **body_args(o, p)},
                                   f"drop {self.name}"))

    def cancel(self):
        self.centre = None

    def outline(self, r):
        k = 48
        t = np.linspace(0, 2 * np.pi, k, endpoint=False)
        return np.stack([np.cos(t), np.sin(t)], 1) * r

    def decorate(self, decor, cursor):
        if self.centre is not None and self.radius > 0:
            pts = self.outline(self.radius) + self.centre
            for i in range(len(pts)):
                decor.segments.append((pts[i], pts[(i + 1) % len(pts)], 1.5, PREVIEW))
            decor.segments.append((self.centre, cursor, 1.0, PREVIEW_DIM))
