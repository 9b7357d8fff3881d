"""Polygon tool: click points; Enter (or a click on the first point) makes a body of that outline,
concave or not (its convex pieces: physics.decompose); the preview shows the pieces."""
from __future__ import annotations

import numpy as np

from .base import PREVIEW, PREVIEW_DIM, Tool
from .outline import make_outline_body, piece_segments


class PolygonTool(Tool):
    name = "polygon"
    help = ("click points; Enter (or click the first point) makes the outline, concave too (the preview "
            "shows its convex pieces); Backspace removes a point; Esc cancels")

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
        """Make the body: the outline as clicked, concave or not, decomposed into convex pieces
        (app.tools.outline).  A refusal says why beside the last point and keeps the points, so
        the user can go on clicking."""
        ed = self.editor
        at = self.points[-1] if self.points else None
        if len(self.points) < 3:
            have = f"{len(self.points)} so far" if self.points else "none yet"
            ed.hint(f"a polygon needs at least 3 points ({have}): click more, Esc cancels", at=at)
            return
        if make_outline_body(ed, np.array(self.points), "create polygon", at,
                             ". Click another point, Backspace removes the last, Esc cancels"):
            self.points = []

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
            decor.segments += piece_segments(pts)      # the convex pieces it will be made of
        for i in range(len(self.points) - 1):
            decor.segments.append((self.points[i], self.points[i + 1], 1.5, PREVIEW))
        decor.segments.append((self.points[-1], cursor, 1.0, PREVIEW_DIM))
        for q in self.points:
            decor.points.append((q, 4.0, PREVIEW))
