"""Polygon tool: click points; Enter (or a click on the first point) makes their convex hull."""
from __future__ import annotations

import numpy as np

import physics

from ..commands import AddBody
from .base import PREVIEW, PREVIEW_DIM, Tool, body_args


class PolygonTool(Tool):
    name = "polygon"
    help = "click points; Enter (or click the first point) makes their convex hull; Esc cancels"

    def __init__(self, editor):
        super().__init__(editor)
        self.points: list[np.ndarray] = []

    def press(self, p, button, mods):
        p = np.array(p, dtype=float)
        if len(self.points) >= 3 and np.hypot(*(p - self.points[0])) * self.editor.camera.scale < 10:
            self.finish()
            return
        self.points.append(p)

    def finish(self):
        pts = np.array(self.points)
        self.points = []
        if len(pts) < 3:
            return
        try:
            shape = physics.Polygon.hull(pts)
        except ValueError as exc:
            self.editor.notify(f"polygon refused: {exc}", error=True)
            return
        # vertices about the centroid, body placed at the centroid
        c = shape.centroid
        shape = physics.Polygon(shape.vertices - c)
        self.editor.create(AddBody({"shape": shape, **body_args(self.editor.tool_options, c)}, "create polygon"))

    def key(self, symbol) -> bool:
        from pyglet.window import key as K
        if symbol in (K.ENTER, K.RETURN):
            self.finish()
            return True
        if symbol == K.ESCAPE and self.points:
            self.points = []
            return True
        if symbol == K.BACKSPACE and self.points:
            self.points.pop()
            return True
        return False

    def cancel(self):
        self.points = []

    def decorate(self, decor, cursor):
        if not self.points:
            return
        pts = self.points + [np.array(cursor)]
        if len(pts) >= 3:
            try:
                h = physics.Polygon.hull(np.array(pts)).vertices
                for i in range(len(h)):
                    decor.segments.append((h[i], h[(i + 1) % len(h)], 1.0, PREVIEW_DIM))
            except ValueError:
                pass
        for i in range(len(self.points) - 1):
            decor.segments.append((self.points[i], self.points[i + 1], 1.5, PREVIEW))
        decor.segments.append((self.points[-1], cursor, 1.0, PREVIEW_DIM))
        for q in self.points:
            decor.points.append((q, 4.0, PREVIEW))
