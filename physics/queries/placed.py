"""A query shape placed in the world: its core as a (k, 2) array and its radius."""
from __future__ import annotations

import math

import numpy as np

from ..geometry.capsule import Capsule, Segment
from ..geometry.chain import ChainSegment
from ..geometry.shapes import Circle, Polygon
from ..validate import finite_num, finite_vec


def placed_core(shape, position, angle) -> tuple[np.ndarray, float]:
    """(world core vertices (CCW), radius) of ``shape`` at ``position`` turned by ``angle``;
    ValueError naming the argument for anything else (a Chain: cast or overlap its segments)."""
    p = finite_vec(position, "position")
    a = finite_num(angle, "angle")
    if isinstance(shape, Circle):
        local = np.asarray(shape.offset, float).reshape(1, 2)
    elif isinstance(shape, (Polygon, Capsule, Segment, ChainSegment)):
        local = np.asarray(shape.vertices, float)
    else:
        raise ValueError(f"shape: expected a physics.Polygon, Circle, Capsule or Segment, got {type(shape).__name__}")
    c, s = math.cos(a), math.sin(a)
    rot = np.array([[c, -s], [s, c]])
    return np.ascontiguousarray(local @ rot.T + p), float(shape.radius)
