"""Sketch tool: drag a closed outline freehand; on release the stroke is simplified
(Ramer-Douglas-Peucker) and becomes one body of that outline, concave or not (app.tools.outline).
A stroke that crosses itself or encloses no area gets a hint, not a body."""
from __future__ import annotations

import numpy as np

from .base import PREVIEW, PREVIEW_DIM, Tool
from .outline import make_outline_body

TOLERANCE_PX = 3.0      # RDP tolerance on screen: wobbles of the hand below 3 px go
SAMPLE_PX = 2.0         # a new stroke point once the pointer moved this far


def rdp(points: np.ndarray, eps: float) -> np.ndarray:
    """Ramer-Douglas-Peucker (Ramer 1972; Douglas and Peucker 1973): keep the point farthest
    from the chord while it is farther than ``eps``, recursing on both halves (iterative stack)."""
    n = len(points)
    if n < 3:
        return points.copy()
    keep = np.zeros(n, bool)
    keep[0] = keep[-1] = True
    stack = [(0, n - 1)]
    while stack:
        i, j = stack.pop()
        if j <= i + 1:
            continue
        a, b = points[i], points[j]
        d = b - a
        ln = np.hypot(*d)
        rel = points[i + 1:j] - a
        dist = np.abs(d[0] * rel[:, 1] - d[1] * rel[:, 0]) / ln if ln > 0 else np.hypot(rel[:, 0], rel[:, 1])
        k = int(np.argmax(dist))
        if dist[k] > eps:
            m = i + 1 + k
            keep[m] = True
            stack += [(i, m), (m, j)]
    return points[keep]


def simplified_outline(stroke, scale: float) -> np.ndarray:
    """The stroke as a closed outline: RDP at TOLERANCE_PX on screen; the closing point dropped
    when the stroke ends where it began."""
    pts = rdp(np.asarray(stroke, dtype=np.float64), TOLERANCE_PX / scale)
    if len(pts) > 3 and np.hypot(*(pts[-1] - pts[0])) * scale < 4 * TOLERANCE_PX:
        pts = pts[:-1]
    return pts


class SketchTool(Tool):
    name = "sketch"
    help = "drag a closed outline freehand: it is simplified and becomes a body (concave too); Esc cancels"

    def __init__(self, editor):
        super().__init__(editor)
        self.stroke: list[np.ndarray] = []

    def press(self, p, button, mods):
        self.stroke = [np.array(p, dtype=float)]

    def drag(self, p):
        p = np.array(p, dtype=float)
        if self.stroke and np.hypot(*(p - self.stroke[-1])) * self.editor.camera.scale >= SAMPLE_PX:
            self.stroke.append(p)

    def release(self, p):
        if not self.stroke:
            return
        self.drag(p)
        stroke, self.stroke = self.stroke, []
        pts = simplified_outline(stroke, self.editor.camera.scale)
        if len(pts) < 3:
            self.editor.hint("sketch: drag around a closed outline (that stroke is a line or a dot)", at=stroke[-1])
            return
        make_outline_body(self.editor, pts, "sketch body", stroke[-1], ": draw it again without crossing")

    def key(self, symbol) -> bool:
        from pyglet.window import key as K
        if symbol == K.ESCAPE and self.stroke:
            self.stroke = []
            return True
        return False

    def cancel(self):
        self.stroke = []

    def decorate(self, decor, cursor):
        s = self.stroke
        for i in range(len(s) - 1):
            decor.segments.append((s[i], s[i + 1], 1.5, PREVIEW))
        if len(s) > 2:
            decor.segments.append((s[-1], s[0], 1.0, PREVIEW_DIM))    # the closing edge
