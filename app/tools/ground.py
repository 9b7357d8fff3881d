"""Ground tool: click points of a static chain (physics.Chain: smooth, one-sided ground, solid
below); Enter, a double click or a right click finishes; Backspace removes a point."""
from __future__ import annotations

import time

import numpy as np

import physics

from ..commands import AddBody
from .base import PREVIEW, PREVIEW_DIM, Tool, body_args

DOUBLE_CLICK_S = 0.35


def ground_points(points) -> np.ndarray:
    """Points ordered right to left, so the chain is solid below them (Box2D's convention: the
    free side is on the left of the direction from point to point)."""
    pts = np.asarray(points, dtype=np.float64)
    return pts[::-1].copy() if pts[-1, 0] > pts[0, 0] else pts


class GroundTool(Tool):
    name = "ground"
    help = "click points of static ground (a smooth chain); Enter, double or right click finishes; Esc cancels"

    def __init__(self, editor):
        super().__init__(editor)
        self.points: list[np.ndarray] = []
        self._last_press = -1.0

    def press(self, p, button, mods):
        p = np.array(p, dtype=float)
        now = time.monotonic()
        near = self.points and np.hypot(*(p - self.points[-1])) * self.editor.camera.scale < 6
        if near and now - self._last_press < DOUBLE_CLICK_S:
            self._last_press = -1.0
            self.finish()
            return
        self._last_press = now
        if near:
            return
        self.points.append(p)

    def right_click(self, p) -> bool:
        if not self.points:
            return False
        self.finish()
        return True

    def finish(self):
        ed = self.editor
        at = self.points[-1] if self.points else None
        if len(self.points) < 2:
            ed.hint("ground needs at least 2 points: click more, Esc cancels", at=at)
            return
        pts = ground_points(self.points)
        origin = pts.mean(axis=0)
        try:
            shape = physics.Chain(pts - origin)
        except ValueError as exc:
            ed.hint(f"no ground: {exc}", at=at)
            return
        self.points = []
        opts = dict(body_args(ed.tool_options, origin), kind="static")
        ed.create(AddBody({"shape": shape, **opts}, "create ground"))

    def key(self, symbol) -> bool:
        from pyglet.window import key as K
        if symbol in (K.ENTER, K.RETURN) and self.points:
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
        for i in range(len(self.points) - 1):
            decor.segments.append((self.points[i], self.points[i + 1], 2.0, PREVIEW))
        decor.segments.append((self.points[-1], cursor, 1.0, PREVIEW_DIM))
        for q in self.points:
            decor.points.append((q, 4.0, PREVIEW))
