"""Polygon tool: click points; Enter (or a click on the first point) makes their convex hull."""
from __future__ import annotations

import numpy as np

import physics

from ..commands import AddBody
from .base import PREVIEW, PREVIEW_DIM, Tool, body_args


class PolygonTool(Tool):
    name = "polygon"
    help = ("click points; Enter (or click the first point) makes their convex hull (a concave "
            "outline becomes its hull until compound shapes land); Backspace removes a point; Esc cancels")

    def __init__(self, editor):
        super().__init__(editor)
        self.points: list[np.ndarray] = []

    def press(self, p, button, mods):
        p = np.array(p, dtype=float)
        scale = self.editor.camera.scale
        if len(self.points) >= 3 and np.hypot(*(p - self.points[0])) * scale < 10:
            self.finish()
            return
        if self.points and np.hypot(*(p - self.points[-1])) * scale < 4:
            self.editor.hint("that point is on the last one: click somewhere else", at=p)
            return
        self.points.append(p)

    def finish(self):
        """Make the polygon: the convex hull of the points, centred on its centroid.  Every refusal
        says why beside the last point and keeps the points, so the user can go on clicking."""
        ed = self.editor
        at = self.points[-1] if self.points else None
        if len(self.points) < 3:
            have = f"{len(self.points)} so far" if self.points else "none yet"
            ed.hint(f"a polygon needs at least 3 points ({have}): click more, Esc cancels", at=at)
            return
        pts = np.array(self.points)
        try:
            shape = physics.Polygon.hull(pts)
        except ValueError as exc:
            ed.hint(f"no polygon: {exc}. Click another point, Backspace removes the last, Esc cancels", at=at)
            return
        self.points = []
        c = shape.centroid            # vertices about the centroid, body placed at the centroid
        shape = physics.Polygon(shape.vertices - c)
        n_before = len(ed.world.bodies)
        ed.create(AddBody({"shape": shape, **body_args(ed.tool_options, c)}, "create polygon"))
        if len(shape.vertices) < len(pts) and len(ed.world.bodies) > n_before:
            ed.hint(f"made the convex hull of the outline ({len(shape.vertices)} of {len(pts)} points): "
                    "concave bodies come with compound shapes", at=at, error=False)

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
