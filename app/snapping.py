"""Grid and angle snapping (toggled with G or in the Tools section): creation tools and the
selection handles round points to the grid and rotations to the angle step."""
from __future__ import annotations

import math

import numpy as np


class Snap:
    """``on``: snapping active; ``grid`` (m, > 0) and ``angle`` (degrees, > 0) steps."""

    def __init__(self, grid: float = 0.5, angle: float = 15.0):
        self.on = False
        self.grid = grid
        self.angle = angle

    def set_steps(self, grid=None, angle=None):
        """Change the steps; ValueError names the field if one is not a finite number > 0."""
        for name, v in (("grid", grid), ("angle", angle)):
            if v is not None and not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise ValueError(f"snap {name}: must be > 0, got {v!r}")
        self.grid = float(grid) if grid is not None else self.grid
        self.angle = float(angle) if angle is not None else self.angle

    def point(self, p):
        """``p`` (m) on the grid while snapping, else unchanged."""
        p = np.asarray(p, dtype=np.float64)
        return np.round(p / self.grid) * self.grid if self.on else p

    def rotation(self, radians: float) -> float:
        """A rotation rounded to the angle step while snapping (radians)."""
        if not self.on:
            return radians
        step = math.radians(self.angle)
        return round(radians / step) * step
