"""Convex decomposition of a simple (possibly concave) polygon: ``decompose(outline)``.

Two stages:

1. Ear-clipping triangulation by mapbox-earcut (a maintained C++ library; Held 2001's
   z-order hashed ear test).
2. Hertel-Mehlhorn merging (Hertel and Mehlhorn 1983; ``hertel_mehlhorn``): remove every
   diagonal whose removal leaves a convex piece.  Each remaining diagonal is essential at
   one of its ends, a reflex vertex, and a reflex vertex keeps at most two essential
   diagonals (three would make its interior angle 360 degrees or more), so there are at
   most 2r + 1 pieces for r reflex vertices, at most four times the optimum.

Collinear outline vertices are dropped first (a piece cannot have them); repeated
vertices, self-intersections (a Shamos-Hoey sweep, ``simplicity``) and outlines without
area are refused with a ValueError that names the problem.  Every stage is O(n log n) or
close to it (earcut's z-order hashing makes its ear tests near-constant in practice).  Every piece carries the outline it came from (``piece.outline``),
so a scene file can store what the user drew.
"""
from __future__ import annotations

from collections import deque

import mapbox_earcut
import numpy as np

from .hertel_mehlhorn import merge, turn
from .shapes import MAX_POLYGON_VERTICES, Polygon, _as_points, _signed_area
from .simplicity import first_meeting

# a turn whose sine is below this counts as straight (the 4x margin over Polygon's own
# collinearity test keeps every merged piece acceptable to Polygon)
_STRAIGHT_SINE = 4e-9


def _clean(outline) -> np.ndarray:
    """CCW outline without collinear vertices; ValueError for repeated or too few vertices."""
    p = _as_points(outline, "outline")
    if len(p) < 3:
        raise ValueError(f"outline needs at least 3 vertices, got {len(p)}")
    scale = float(np.max(np.abs(p - p.mean(axis=0))))
    step = np.hypot(*(np.roll(p, -1, axis=0) - p).T)
    if scale == 0.0 or np.any(step <= 1e-12 * scale):
        i = int(np.argmin(step))
        raise ValueError(f"outline has repeated vertices at index {i} and {(i + 1) % len(p)}")
    q = p[_turning(p.tolist())]
    if len(q) >= 3:
        found = first_meeting(q.tolist())
        if found:
            i, k = found
            m = len(q)
            raise ValueError(f"outline is self-intersecting: edge {i} ({i}-{(i + 1) % m}) meets edge {k} "
                             f"({k}-{(k + 1) % m})")
    if len(q) < 3 or abs(_signed_area(q - q.mean(axis=0))) <= 1e-12 * scale * scale:
        raise ValueError("outline has zero area (its vertices lie on one line)")
    return q if _signed_area(q - q.mean(axis=0)) > 0 else q[::-1].copy()


def _turning(p: list) -> list[int]:
    """Indices of the vertices that turn: straight (and reversing) ones dropped, repeatedly, as
    dropping one changes its neighbours' turns.  A stack pass (as in Andrew's monotone chain),
    then the wrap-around at the start: linear time."""
    def straight(a, b, c):
        return abs(turn(p, a, b, c)) <= _STRAIGHT_SINE

    keep = []
    for i in range(len(p)):
        while len(keep) >= 2 and straight(keep[-2], keep[-1], i):
            keep.pop()
        keep.append(i)
    keep = deque(keep)
    changed = True
    while changed and len(keep) >= 3:
        changed = False
        while len(keep) >= 3 and straight(keep[-2], keep[-1], keep[0]):
            keep.pop()
            changed = True
        while len(keep) >= 3 and straight(keep[-1], keep[0], keep[1]):
            keep.popleft()
            changed = True
    return list(keep)


def decompose(outline) -> list[Polygon]:
    """Convex pieces (physics.Polygon, at most 64 vertices each) of a simple polygon outline.

    ``outline``: (x, y) vertices in either winding.  The pieces cover the outline exactly
    and do not overlap; there are at most 2r + 1 of them for r reflex vertices.  ValueError
    names the problem for fewer than 3 vertices, repeated vertices, a self-intersecting
    outline or one without area.  Each piece's ``outline`` is the cleaned CCW outline.

    >>> import physics
    >>> pieces = physics.decompose([(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)])
    >>> len(pieces), round(sum(p.area for p in pieces), 12)
    (2, 5.0)
    """
    p = _clean(outline)
    tri = mapbox_earcut.triangulate_float64(p, np.array([len(p)], dtype=np.uint32)).reshape(-1, 3)
    if len(tri) != len(p) - 2:
        raise ValueError("outline could not be triangulated (is it self-intersecting or degenerate?)")
    pts = p.tolist()
    triangles = []
    for t in tri.tolist():
        if turn(pts, t[0], t[1], t[2]) < 0:  # earcut's winding is not promised: make each CCW
            t = [t[0], t[2], t[1]]
        triangles.append(t)
    pieces = merge(pts, triangles, MAX_POLYGON_VERTICES, _STRAIGHT_SINE)
    source = p.copy()
    source.setflags(write=False)
    out = []
    for piece in pieces:
        try:
            poly = Polygon(p[piece])
        except ValueError as exc:
            raise ValueError(f"outline is degenerate: a convex piece of it is refused ({exc})") from None
        poly.outline = source
        out.append(poly)
    return out
