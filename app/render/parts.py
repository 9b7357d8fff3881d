"""A body's fixtures as drawable parts (issue 13): every fixture drawn by itself.

``RenderData.fixtures`` lists each fixture's shape code, radius and vertex rows; this module
turns them into what the layers draw, in one numpy pass per kind (no loop over fixtures):

- convex polygons as fans (their own vertex rows);
- rounded polygons and capsules as the convex outline of their Minkowski sum with a disc:
  each core vertex becomes an arc of ``ARC`` points from the normal of the edge before it to
  the normal of the edge after it (a capsule is a two-vertex rounded polygon, as in Box2D v3,
  so its ends become half circles);
- circles as discs at the fixture's own centre;
- segments and chain segments as lines.
"""
from __future__ import annotations

import numpy as np

from physics.store.fixtures import CAPSULE, CHAIN_SEGMENT, CIRCLE, SEGMENT

ARC = 8        # points per rounded corner: 8 keeps a 1 px chord error up to ~50 px radii on screen


class Parts:
    """The fixtures of one render data: ``polys`` (vertices, vstart, vcount, centre, body row,
    fixture id), ``circles`` (centre, radius, body row, fixture id), ``lines`` (p0, p1, body row)."""

    def __init__(self, rd):
        fx = rd.fixtures
        shape, radius = fx["shape"], fx["radius"]
        vcount = fx["vcount"].astype(np.int64)
        body = fx["body"].astype(np.int64)
        flat = (shape != CIRCLE) & (shape != CAPSULE) & (shape != SEGMENT) & (shape != CHAIN_SEGMENT)
        sharp = np.nonzero(flat & (radius <= 0) & (vcount >= 3))[0]
        round_ = np.nonzero(((flat & (radius > 0)) | (shape == CAPSULE)) & (vcount >= 2))[0]
        V = rd.vertices
        rv, rstart, rcount = rounded_outlines(V, fx["vstart"][round_], vcount[round_], radius[round_])
        base = len(V)
        self.vertices = np.concatenate([V, rv]) if len(rv) else V
        self.vstart = np.concatenate([fx["vstart"][sharp].astype(np.int64), rstart + base])
        self.vcount = np.concatenate([vcount[sharp], rcount])
        self.body = np.concatenate([body[sharp], body[round_]])
        self.fixture = np.concatenate([fx["id"][sharp], fx["id"][round_]]).astype(np.int64)
        self.centre = _means(self.vertices, self.vstart, self.vcount)
        ci = np.nonzero(shape == CIRCLE)[0]
        self.circle_centre, self.circle_radius, self.circle_body = fx["center"][ci], radius[ci], body[ci]
        self.circle_fixture = fx["id"][ci].astype(np.int64)
        li = np.nonzero(((shape == SEGMENT) | (shape == CHAIN_SEGMENT)) & (vcount >= 2))[0]
        s = fx["vstart"][li].astype(np.int64)
        self.line_p0, self.line_p1, self.line_body = V[s], V[s + 1], body[li]


def _means(V, vstart, vcount):
    """Each part's vertex mean (inside a convex part: the fan's centre)."""
    if not len(vcount):
        return np.zeros((0, 2))
    rows = np.repeat(vstart, vcount) + np.arange(vcount.sum()) - np.repeat(np.cumsum(vcount) - vcount, vcount)
    sums = np.add.reduceat(V[rows], np.cumsum(vcount) - vcount, axis=0)
    return sums / vcount[:, None]


def rounded_outlines(V, vstart, vcount, radius):
    """Outlines of rounded convex polygons (counter-clockwise cores ``V[vstart:vstart+vcount]``
    grown by ``radius``): (vertices, vstart, vcount) with ``ARC`` points per core vertex."""
    n = len(vcount)
    if not n:
        return np.zeros((0, 2)), np.zeros(0, np.int64), np.zeros(0, np.int64)
    vstart = vstart.astype(np.int64)
    first = np.repeat(np.cumsum(vcount) - vcount, vcount)
    k = np.arange(vcount.sum()) - first
    cnt = np.repeat(vcount, vcount)
    base = np.repeat(vstart, vcount)
    cur = V[base + k]
    prev = V[base + (k - 1) % cnt]
    nxt = V[base + (k + 1) % cnt]
    # outward normal of a counter-clockwise edge d is (d_y, -d_x)
    d1, d2 = cur - prev, nxt - cur
    a1 = np.arctan2(-d1[:, 0], d1[:, 1])
    a2 = np.arctan2(-d2[:, 0], d2[:, 1])
    sweep = np.mod(a2 - a1, 2 * np.pi)
    t = np.linspace(0.0, 1.0, ARC)
    ang = a1[:, None] + sweep[:, None] * t[None, :]
    r = np.repeat(radius, vcount)[:, None]
    pts = np.stack([cur[:, 0:1] + r * np.cos(ang), cur[:, 1:2] + r * np.sin(ang)], axis=2).reshape(-1, 2)
    out_count = vcount.astype(np.int64) * ARC
    return pts, np.cumsum(out_count) - out_count, out_count
