"""Concave outlines from the polygon and sketch tools: decomposed into convex pieces
(physics.decompose: ear clipping + Hertel-Mehlhorn), one body whose fixtures are the pieces."""
from __future__ import annotations

import numpy as np

import physics

from ..commands import AddBody
from .base import body_args

PIECES = (0.55, 0.85, 1.0, 0.55)     # the preview's piece edges (the diagonals show the split)


def area_centroid(pts: np.ndarray) -> np.ndarray:
    """Centroid of a simple polygon's area (shoelace formula); the vertex mean if it has none."""
    x, y = pts[:, 0], pts[:, 1]
    xn, yn = np.roll(x, -1), np.roll(y, -1)
    cross = x * yn - xn * y
    a = 0.5 * cross.sum()
    if abs(a) < 1e-12:
        return pts.mean(axis=0)
    return np.array([((x + xn) * cross).sum(), ((y + yn) * cross).sum()]) / (6.0 * a)


def make_outline_body(editor, points, label: str, at, advice: str = "") -> bool:
    """Create one body from a simple outline (world points): its convex pieces about the area
    centroid, the body placed there.  A bad outline (crossing itself, no area) is a hint beside
    ``at`` (followed by ``advice``), not an exception; returns whether a body was made."""
    pts = np.asarray(points, dtype=np.float64)
    c = area_centroid(pts)
    try:
        pieces = physics.decompose(pts - c)
    except ValueError as exc:
        editor.hint(f"no body: {exc}{advice}", at=at)
        return False
    n_before = len(editor.world.bodies)
    editor.create(AddBody({"shape": pieces, **body_args(editor.tool_options, c)}, label))
    made = len(editor.world.bodies) > n_before
    if made and len(pieces) > 1:
        editor.hint(f"a concave body of {len(pieces)} convex pieces", at=at, error=False)
    return made


def piece_segments(points):
    """The pieces' edges of the outline ``points`` for a preview ([] while it is not simple)."""
    try:
        pieces = physics.decompose(np.asarray(points, dtype=np.float64))
    except ValueError:
        return []
    out = []
    for p in pieces:
        v = p.vertices
        out += [(v[i], v[(i + 1) % len(v)], 1.0, PIECES) for i in range(len(v))]
    return out
