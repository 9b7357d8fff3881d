"""Capsules and segments: shapes made of one line segment (a capsule rounds it by a radius).

Box2D v3 treats a capsule as a two-vertex rounded polygon, and so does the narrow phase here:
the capsule's core is the segment a-b.  A segment has no area, so it carries no mass: it is
for static and kinematic bodies (ground, walls), and a dynamic body made only of segments is
refused when it is added.
"""
from __future__ import annotations

import math

import numpy as np

from .rounded import rounded_mass
from .shapes import MAX_COORDINATE, Shape, _as_points, _check_mass_scale, _positive


def _ends(a, b, what: str) -> np.ndarray:
    pts = _as_points([a, b], f"{what} ends")
    d = pts[1] - pts[0]
    scale = max(1.0, float(np.max(np.abs(pts))))
    if math.hypot(d[0], d[1]) <= 1e-12 * scale:
        raise ValueError(f"{what}: its two ends coincide (a {what} needs a length)")
    return pts


class Capsule(Shape):
    """A capsule: the points within ``radius`` of the segment from ``a`` to ``b`` (body coordinates).

    ValueError when the ends coincide, a coordinate is not finite, or the radius is not a
    positive finite number.
    """

    kind = "capsule"
    """The shape type's name in scene files: "capsule"."""

    def __init__(self, a, b, radius: float):
        """End centres ``a``, ``b`` (m, body coordinates) and ``radius`` (m, > 0)."""
        pts = _ends(a, b, "capsule")
        r = _positive(radius, "capsule radius")
        if r > MAX_COORDINATE:
            raise ValueError(f"capsule radius {r:g} m is too large to represent")
        self.vertices = pts
        """The two end centres (m, body coordinates) as a read-only (2, 2) array."""
        self.vertices.setflags(write=False)
        self.radius = r
        """Radius in metres (> 0)."""
        with np.errstate(over="ignore"):
            m, _, inertia = self.mass_properties(1.0)
        _check_mass_scale(m, inertia, "capsule", 2 * (self.length + r))

    @property
    def a(self) -> np.ndarray:
        """First end centre (m, body coordinates)."""
        return self.vertices[0]

    @property
    def b(self) -> np.ndarray:
        """Second end centre (m, body coordinates)."""
        return self.vertices[1]

    @property
    def length(self) -> float:
        """Distance between the end centres (m)."""
        d = self.vertices[1] - self.vertices[0]
        return math.hypot(d[0], d[1])

    @property
    def spec(self) -> dict:
        """The scene-file form: ``{"capsule": {"a": [x, y], "b": [x, y], "radius": r}}``."""
        return {"capsule": {"a": self.vertices[0].tolist(), "b": self.vertices[1].tolist(), "radius": self.radius}}

    @property
    def area(self) -> float:
        """Area in m^2: 2 r L + pi r^2 (a rectangle and two half discs)."""
        return 2.0 * self.radius * self.length + math.pi * self.radius * self.radius

    @property
    def centroid(self) -> np.ndarray:
        """The midpoint of the two ends (m, body coordinates)."""
        return 0.5 * (self.vertices[0] + self.vertices[1])

    @property
    def bounding_radius(self) -> float:
        """Radius (m) of the smallest circle about the centroid holding the capsule: L/2 + r."""
        return 0.5 * self.length + self.radius

    def mass_properties(self, density: float):
        """(mass kg, centroid (2,), inertia about the centroid kg m^2) for ``density`` (kg/m^2).

        Exact: a rectangle 2r x L plus two half discs (geometry/rounded.py)."""
        area, c, j = rounded_mass(np.array(self.vertices), self.radius)
        return density * area, c, density * j

    def __repr__(self):
        return f"Capsule({self.vertices[0].tolist()}, {self.vertices[1].tolist()}, {self.radius})"

    def __eq__(self, other):
        return (isinstance(other, Capsule) and np.array_equal(self.vertices, other.vertices)
                and self.radius == other.radius)

    __hash__ = None


class Segment(Shape):
    """A line segment from ``a`` to ``b`` (body coordinates): zero thickness and no area.

    Two-sided; for static and kinematic bodies (a dynamic body needs a shape with area).
    ValueError when the ends coincide or a coordinate is not finite.
    """

    kind = "segment"
    """The shape type's name in scene files: "segment"."""

    radius = 0.0
    """A segment has no rounding (0 m)."""

    def __init__(self, a, b):
        """Ends ``a`` and ``b`` (m, body coordinates)."""
        self.vertices = _ends(a, b, "segment")
        """The two ends (m, body coordinates) as a read-only (2, 2) array."""
        self.vertices.setflags(write=False)

    @property
    def a(self) -> np.ndarray:
        """First end (m, body coordinates)."""
        return self.vertices[0]

    @property
    def b(self) -> np.ndarray:
        """Second end (m, body coordinates)."""
        return self.vertices[1]

    @property
    def spec(self) -> dict:
        """The scene-file form: ``{"segment": [[x, y], [x, y]]}``."""
        return {"segment": self.vertices.tolist()}

    @property
    def area(self) -> float:
        """0 m^2: a segment has no area (and no mass)."""
        return 0.0

    @property
    def centroid(self) -> np.ndarray:
        """The midpoint (m, body coordinates)."""
        return 0.5 * (self.vertices[0] + self.vertices[1])

    @property
    def bounding_radius(self) -> float:
        """Half the length (m): the circle about the midpoint holding the segment."""
        d = self.vertices[1] - self.vertices[0]
        return 0.5 * math.hypot(d[0], d[1])

    def mass_properties(self, density: float):
        """(0, midpoint, 0): no area, no mass, whatever the density."""
        return 0.0, self.centroid, 0.0

    def __repr__(self):
        return f"Segment({self.vertices[0].tolist()}, {self.vertices[1].tolist()})"

    def __eq__(self, other):
        return isinstance(other, Segment) and np.array_equal(self.vertices, other.vertices)

    __hash__ = None
