"""What queries return: RayHit, ShapeHit and the structured dtype of ray_cast_many."""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

#: ray_cast_many's rows: ids of the fixture and its body (-1: miss), hit point and normal, fraction (-1: miss)
RAY_DTYPE = np.dtype([("fixture", np.int64), ("body", np.int64), ("point", np.float64, (2,)),
                      ("normal", np.float64, (2,)), ("fraction", np.float64)])


class RayHit(NamedTuple):
    """One hit of a ray cast: the fixture and body hit, the world point, the surface normal there
    and the fraction along the ray (0 at its start, 1 at its end).  A ray starting inside a shape
    hits it at fraction 0 with normal (0, 0)."""

    fixture: object
    """The physics.Fixture hit."""
    body: object
    """The physics.Body the fixture belongs to."""
    point: tuple
    """World point of the hit (m): start + fraction (end - start)."""
    normal: tuple
    """Unit outward normal of the fixture's surface at the point ((0, 0) for a start inside)."""
    fraction: float
    """Fraction of the segment from start to end at the hit, in [0, 1]."""


class ShapeHit(NamedTuple):
    """The first contact of a shape cast: the fixture met, the fraction of the translation, the
    contact point on the fixture's surface and the normal there (pointing from the fixture toward
    the cast shape; (0, 0) when the shape starts in contact, fraction 0)."""

    fixture: object
    """The physics.Fixture met first."""
    body: object
    """The physics.Body of that fixture."""
    fraction: float
    """Fraction of the translation travelled before contact, in [0, 1]."""
    point: tuple
    """World contact point on the fixture's surface (m)."""
    normal: tuple
    """Unit normal at the contact, from the fixture toward the cast shape."""
