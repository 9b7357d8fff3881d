"""Chains: one-sided smooth polylines for static ground (Box2D's chain shape).

A chain is a run of chain segments, each with ghost vertices (its neighbours along the
chain) that let the narrow phase keep contacts smooth where segments meet: a box sliding
over the joint of two collinear segments never catches the second one's end (the ghost
collision problem; Catto, "Ghost collisions", box2d.org 2020).

Sides follow Box2D: the collision side of a segment is to the right of its direction (its
normal is the direction turned by -90 degrees), so the solid is to its left.  Ground listed
from right to left is solid below; a loop listed counter-clockwise is solid inside.  Shapes
behind a segment pass through it.  An open chain's two ends act as convex corners: a body
rolling off an end is pushed around it as around a cliff edge.
"""
from __future__ import annotations

import math

import numpy as np

from .shapes import Shape, _as_points


class ChainSegment(Shape):
    """One segment of a :class:`Chain` (made by the chain; a fixture's shape): its two ends,
    its ghost vertices and the chain it belongs to."""

    kind = "chain_segment"
    """The shape type's name: "chain_segment" (scene files store the whole chain)."""

    radius = 0.0
    """A chain segment has no rounding (0 m)."""

    def __init__(self, chain, index: int, a, b, ghost_a, ghost_b):
        """Segment ``index`` of ``chain`` from ``a`` to ``b``; ``ghost_a`` precedes a, ``ghost_b`` follows b."""
        self.chain = chain
        """The Chain this segment is part of."""
        self.index = index
        """Position of this segment in its chain (0 first)."""
        self.vertices = np.array([a, b], dtype=np.float64)
        """The two ends (m, body coordinates) as a read-only (2, 2) array."""
        self.vertices.setflags(write=False)
        self.ghost = np.array([ghost_a, ghost_b], dtype=np.float64)
        """Ghost vertices (m, body coordinates): the one before the first end and the one after the second."""
        self.ghost.setflags(write=False)

    @property
    def spec(self) -> dict:
        """The scene-file form of the whole chain (a segment is never saved alone)."""
        return self.chain.spec

    @property
    def area(self) -> float:
        """0 m^2: a chain has no area (and no mass)."""
        return 0.0

    @property
    def centroid(self) -> np.ndarray:
        """The segment's midpoint (m, body coordinates)."""
        return 0.5 * (self.vertices[0] + self.vertices[1])

    @property
    def bounding_radius(self) -> float:
        """Half the segment's length (m)."""
        d = self.vertices[1] - self.vertices[0]
        return 0.5 * math.hypot(d[0], d[1])

    def mass_properties(self, density: float):
        """(0, midpoint, 0): no area, no mass."""
        return 0.0, self.centroid, 0.0

    def __repr__(self):
        return f"ChainSegment({self.index} of {self.chain!r})"


class Chain(Shape):
    """A one-sided polyline through ``points`` (body coordinates); ``loop=True`` closes it.

    Solid lies to the left of the direction from point to point, contacts happen on the
    right (Box2D's convention): list ground from right to left, a loop counter-clockwise
    around solid ground.  For static and kinematic bodies.  ValueError for fewer than 2
    points (3 for a loop), repeated consecutive points or non-finite coordinates.
    """

    kind = "chain"
    """The shape type's name in scene files: "chain"."""

    radius = 0.0
    """A chain has no rounding (0 m)."""

    def __init__(self, points, loop: bool = False):
        """``points``: (x, y) pairs (m); ``loop``: join the last point to the first."""
        if not isinstance(loop, (bool, np.bool_)):
            raise ValueError(f"chain loop must be True or False, got {loop!r}")
        pts = _as_points(points, "chain points")
        need = 3 if loop else 2
        if len(pts) < need:
            raise ValueError(f"chain needs at least {need} points{' for a loop' if loop else ''}, got {len(pts)}")
        scale = max(1.0, float(np.max(np.abs(pts))))
        nxt = np.roll(pts, -1, axis=0) if loop else pts[1:]
        steps = np.hypot(*(nxt - pts[: len(nxt)]).T)
        if np.any(steps <= 1e-12 * scale):
            i = int(np.argmin(steps))
            raise ValueError(f"chain has repeated points at index {i} and {(i + 1) % len(pts)}")
        self.points = pts
        """The chain's points (m, body coordinates) as a read-only (n, 2) array."""
        self.points.setflags(write=False)
        self.loop = bool(loop)
        """True when the chain is closed (the last point joins the first)."""
        self.segments = self._segments()
        """The chain's segments (ChainSegment), in order: the shapes of its fixtures."""

    def _segments(self) -> list[ChainSegment]:
        p = self.points
        n = len(p)
        count = n if self.loop else n - 1
        out = []
        for i in range(count):
            a, b = p[i], p[(i + 1) % n]
            if self.loop or i > 0:
                ga = p[(i - 1) % n]
            else:  # open end: a convex corner (see the module docstring)
                ga = a - _right(b - a)
            if self.loop or i + 2 < n:
                gb = p[(i + 2) % n]
            else:
                gb = b - _right(b - a)
            out.append(ChainSegment(self, i, a, b, ga, gb))
        return out

    @property
    def spec(self) -> dict:
        """The scene-file form: ``{"chain": {"points": [[x, y], ...], "loop": bool}}``."""
        return {"chain": {"points": self.points.tolist(), "loop": self.loop}}

    @property
    def area(self) -> float:
        """0 m^2: a chain has no area."""
        return 0.0

    @property
    def centroid(self) -> np.ndarray:
        """Mean of the points (m, body coordinates)."""
        return self.points.mean(axis=0)

    @property
    def bounding_radius(self) -> float:
        """Distance (m) from the centroid to the farthest point."""
        return float(np.max(np.hypot(*(self.points - self.centroid).T)))

    def mass_properties(self, density: float):
        """(0, centroid, 0): no area, no mass."""
        return 0.0, self.centroid, 0.0

    def __repr__(self):
        return f"Chain({len(self.points)} points{', loop' if self.loop else ''})"

    def __eq__(self, other):
        return isinstance(other, Chain) and self.loop == other.loop and np.array_equal(self.points, other.points)

    __hash__ = None


def _right(e: np.ndarray) -> np.ndarray:
    """``e`` turned by -90 degrees (Box2D's b2RightPerp): a segment's collision-side normal times its length."""
    return np.array([e[1], -e[0]])
