"""Rope tool: drag from a body to another body or to the background: a distance joint between
the two points with only a max_length (a rope: it goes slack, never pushes), as long as the drag."""
from __future__ import annotations

from ..picking import bodies_at
from .base import PREVIEW
from .joining import DragJointTool, add_joint


class RopeTool(DragJointTool):
    name = "rope"
    verb = "tie a rope"
    help = "drag from a body to another body (or to the background): a rope as long as the drag"

    def pick(self, p):
        under = bodies_at(self.editor.world, p)
        if not under:
            self.editor.hint("start a rope on a body")
            return None
        return under[0], None

    def finish(self, a, _b, p0, p1):
        under = [x for x in bodies_at(self.editor.world, p1) if x is not a]
        b = under[0] if under else None
        if a.kind == "static" and (b is None or b.kind == "static"):
            self.editor.hint("a rope between static bodies holds nothing")
            return
        pa, pb = tuple(map(float, p0)), tuple(map(float, p1))
        length = ((p1 - p0) ** 2).sum() ** 0.5
        add_joint(self.editor, "distance", a, b, anchor_a=pa, anchor_b=pb, max_length=float(length))

    def decorate(self, decor, cursor):
        if self.start is not None and self.start[0].alive:
            p0 = self.start[2]
            decor.segments.append((p0, cursor, 2.0, PREVIEW))
            decor.points.append((p0, 4.0, PREVIEW))
