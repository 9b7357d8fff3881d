"""2D camera: world <-> screen mapping, pan, zoom at a point, fit to a box."""
from __future__ import annotations

import numpy as np


class Camera:
    """Orthographic camera: ``center`` (world metres) at the middle of the viewport,
    ``scale`` pixels per metre.  Screen coordinates are pyglet's (origin bottom-left)."""

    MIN_SCALE = 0.5
    MAX_SCALE = 5000.0

    def __init__(self, width: int, height: int, center=(0.0, 5.0), scale: float = 40.0):
        self.width = int(width)
        self.height = int(height)
        self.center = np.array(center, dtype=np.float64)
        self.scale = float(scale)

    def resize(self, width: int, height: int) -> None:
        self.width, self.height = max(1, int(width)), max(1, int(height))

    def to_world(self, sx: float, sy: float) -> np.ndarray:
        return self.center + (np.array([sx, sy], dtype=np.float64) - 0.5 * np.array([self.width, self.height])) / self.scale

    def to_screen(self, p) -> np.ndarray:
        return (np.asarray(p, dtype=np.float64) - self.center) * self.scale + 0.5 * np.array([self.width, self.height])

    def pan_pixels(self, dx: float, dy: float) -> None:
        self.center -= np.array([dx, dy]) / self.scale

    def zoom_at(self, sx: float, sy: float, factor: float) -> None:
        """Zoom by ``factor`` keeping the world point under (sx, sy) fixed."""
        before = self.to_world(sx, sy)
        self.scale = float(np.clip(self.scale * factor, self.MIN_SCALE, self.MAX_SCALE))
        after = self.to_world(sx, sy)
        self.center += before - after

    def fit(self, lo, hi, margin: float = 0.06, avoid_left: float = 0.0, avoid_right: float = 0.0) -> None:
        """Show the world box [lo, hi] with a margin; ``avoid_left``/``avoid_right`` pixels are covered
        by panels."""
        lo = np.asarray(lo, dtype=np.float64)
        hi = np.asarray(hi, dtype=np.float64)
        if not (np.all(np.isfinite(lo)) and np.all(np.isfinite(hi))):
            return
        size = np.maximum(hi - lo, 1.0)
        if self.width - avoid_left - avoid_right < 300:
            avoid_left = avoid_right = 0.0
        usable_w = max(100.0, self.width - avoid_left - avoid_right)
        s = min(usable_w / size[0], self.height / size[1]) * (1.0 - 2 * margin)
        self.scale = float(np.clip(s, self.MIN_SCALE, self.MAX_SCALE))
        mid = 0.5 * (lo + hi)
        # shift so the box is centred in the area right of the panels
        self.center = mid - np.array([0.5 * (avoid_left - avoid_right) / self.scale, 0.0])

    def look_at(self, center, scale: float, avoid_left: float = 0.0, avoid_right: float = 0.0) -> None:
        """Put world point ``center`` at the middle of the area between ``avoid_left`` and
        ``avoid_right`` pixels (panels), at ``scale`` pixels per metre."""
        if self.width - avoid_left - avoid_right < 300:
            avoid_left = avoid_right = 0.0
        self.scale = float(np.clip(scale, self.MIN_SCALE, self.MAX_SCALE))
        self.center = np.asarray(center, dtype=np.float64).reshape(2) - \
            np.array([0.5 * (avoid_left - avoid_right) / self.scale, 0.0])

    def matrix(self) -> np.ndarray:
        """World -> clip space as a column-major 3x3 (for a mat3 uniform)."""
        sx = 2.0 * self.scale / self.width
        sy = 2.0 * self.scale / self.height
        m = np.array([[sx, 0.0, -sx * self.center[0]],
                      [0.0, sy, -sy * self.center[1]],
                      [0.0, 0.0, 1.0]], dtype=np.float32)
        return m

    def visible_box(self):
        lo = self.to_world(0, 0)
        hi = self.to_world(self.width, self.height)
        return lo, hi
