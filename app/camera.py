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

    def _place(self, point, rect) -> None:
        """Put world ``point`` at the middle of ``rect`` (x0, y0, x1, y1 window pixels, y down)."""
        if rect is None:
            rect = (0.0, 0.0, self.width, self.height)
        x0, y0, x1, y1 = rect
        offset = np.array([0.5 * (x0 + x1) - 0.5 * self.width, 0.5 * self.height - 0.5 * (y0 + y1)])
        self.center = np.asarray(point, dtype=np.float64).reshape(2) - offset / self.scale

    def fit(self, lo, hi, margin: float = 0.06, rect=None) -> None:
        """Show the world box [lo, hi] with a margin inside ``rect`` (window pixels, y down;
        default: the whole window)."""
        lo = np.asarray(lo, dtype=np.float64)
        hi = np.asarray(hi, dtype=np.float64)
        if not (np.all(np.isfinite(lo)) and np.all(np.isfinite(hi))):
            return
        if rect is None:
            rect = (0.0, 0.0, self.width, self.height)
        size = np.maximum(hi - lo, 1.0)
        w, h = max(100.0, rect[2] - rect[0]), max(100.0, rect[3] - rect[1])
        s = min(w / size[0], h / size[1]) * (1.0 - 2 * margin)
        self.scale = float(np.clip(s, self.MIN_SCALE, self.MAX_SCALE))
        self._place(0.5 * (lo + hi), rect)

    def look_at(self, center, scale: float, rect=None) -> None:
        """Put world point ``center`` at the middle of ``rect`` (window pixels, y down; default:
        the whole window), at ``scale`` pixels per metre."""
        self.scale = float(np.clip(scale, self.MIN_SCALE, self.MAX_SCALE))
        self._place(center, rect)

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
