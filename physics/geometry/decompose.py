"""Convex decomposition of a simple (possibly concave) polygon: ``decompose(outline)``.

Two stages:

1. Ear-clipping triangulation by mapbox-earcut (a maintained C++ library; Held 2001's
   z-order hashed ear test).
2. Hertel-Mehlhorn merging (Hertel and Mehlhorn 1983): remove every diagonal whose removal
   leaves a convex piece, until none is left.  Each remaining diagonal is essential at one
   of its ends, a reflex vertex, and a reflex vertex keeps at most two essential diagonals
   (three would make its interior angle 360 degrees or more), so there are at most 2r + 1
   pieces for r reflex vertices, at most four times the optimum.

Collinear outline vertices are dropped first (a piece cannot have them); repeated
vertices, self-intersections and outlines without area are refused with a ValueError
that names the problem.  Every piece carries the outline it came from (``piece.outline``),
so a scene file can store what the user drew.
"""
from __future__ import annotations

import mapbox_earcut
import numpy as np

from .shapes import MAX_POLYGON_VERTICES, Polygon, _as_points, _signed_area

# a turn whose sine is below this counts as straight (the 4x margin over Polygon's own
# collinearity test keeps every merged piece acceptable to Polygon)
_STRAIGHT_SINE = 4e-9


def _turn(p, a, b, c) -> float:
    """Sine of the turn at b along a -> b -> c (> 0: left, convex for a CCW outline)."""
    e0 = p[b] - p[a]
    e1 = p[c] - p[b]
    return float((e0[0] * e1[1] - e0[1] * e1[0]) / (np.hypot(*e0) * np.hypot(*e1)))


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
    keep = list(range(len(p)))
    changed = True
    while changed and len(keep) >= 3:
        changed = False
        for k in range(len(keep)):
            a, b, c = keep[k - 1], keep[k], keep[(k + 1) % len(keep)]
            if abs(_turn(p, a, b, c)) <= _STRAIGHT_SINE:
                del keep[k]
                changed = True
                break
    q = p[keep]
    if len(q) >= 3:
        _check_simple(q)
    if len(q) < 3 or abs(_signed_area(q - q.mean(axis=0))) <= 1e-12 * scale * scale:
        raise ValueError("outline has zero area (its vertices lie on one line)")
    return q if _signed_area(q - q.mean(axis=0)) > 0 else q[::-1].copy()


def _check_simple(p: np.ndarray) -> None:
    """ValueError naming two edges that cross or touch (non-neighbours), else nothing."""
    n = len(p)
    a, b = p, np.roll(p, -1, axis=0)
    for i in range(n):
        j = np.arange(i + 2, n)
        if i == 0:
            j = j[j != n - 1]   # the last edge is the first one's neighbour
        if not len(j):
            continue
        c, d = a[j], b[j]

        def orient(u, v, w):
            return (v[..., 0] - u[..., 0]) * (w[..., 1] - u[..., 1]) - (v[..., 1] - u[..., 1]) * (w[..., 0] - u[..., 0])
        d1, d2 = orient(a[i], b[i], c), orient(a[i], b[i], d)
        d3, d4 = orient(c, d, a[i]), orient(c, d, b[i])
        hit = (np.sign(d1) != np.sign(d2)) & (np.sign(d3) != np.sign(d4))
        line = (d1 == 0) & (d2 == 0)  # on one line: they meet when their spans along it overlap
        if np.any(line):
            e = b[i] - a[i]
            t0, t1 = (c - a[i]) @ e, (d - a[i]) @ e
            hit &= ~line
            hit |= line & (np.maximum(t0, t1) >= 0) & (np.minimum(t0, t1) <= e @ e)
        if np.any(hit):
            k = int(j[np.argmax(hit)])
            raise ValueError(f"outline is self-intersecting: edge {i} ({i}-{(i + 1) % n}) meets edge {k} "
                             f"({k}-{(k + 1) % n})")


def _merge(p: np.ndarray, pieces: list[list[int]]) -> list[list[int]]:
    """Hertel-Mehlhorn: merge pieces across diagonals while the result stays convex."""
    merged = True
    while merged:
        merged = False
        edges = {}
        for k, piece in enumerate(pieces):
            for t in range(len(piece)):
                edges[(piece[t], piece[(t + 1) % len(piece)])] = k
        for (u, v), k in edges.items():
            m = edges.get((v, u))
            if m is None or m <= k:
                continue
            joined = _join(pieces[k], pieces[m], u, v)
            if len(joined) <= MAX_POLYGON_VERTICES and _convex(p, joined):
                pieces[k] = joined
                del pieces[m]
                merged = True
                break
    return pieces


def _join(a: list[int], b: list[int], u: int, v: int) -> list[int]:
    """Piece a (with edge u -> v) and piece b (with edge v -> u) as one CCW cycle."""
    ia = a.index(v)
    ra = a[ia:] + a[:ia]          # starts at v, ends at u
    ib = b.index(u)
    rb = b[ib:] + b[:ib]          # starts at u, ends at v
    return ra[:-1] + rb[:-1]


def _convex(p, cyc: list[int]) -> bool:
    n = len(cyc)
    return all(_turn(p, cyc[k - 1], cyc[k], cyc[(k + 1) % n]) > _STRAIGHT_SINE for k in range(n))


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
    pieces = []
    for t in tri.tolist():
        if _turn(p, t[0], t[1], t[2]) < 0:  # earcut's winding is not promised: make each CCW
            t = [t[0], t[2], t[1]]
        pieces.append(t)
    pieces = _merge(p, pieces)
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
