"""Chain segments: one-sided segments whose ghost vertices keep contacts smooth.

Segment p1 -> p2 with collision normal n1 = the direction turned by -90 degrees (Box2D's
b2RightPerp); g0 precedes p1 and g3 follows p2 along the chain.  A shape whose centre is
behind the segment does not touch it (one-sided).  A contact normal n found as for a
two-sided segment is then classified on the Gauss map of the chain (Catto, "Ghost
collisions", box2d.org 2020; Box2D v3's b2ClassifyNormal):

* pointing toward an end at a convex corner (the chain turns away there): kept while it lies
  between the two segments' normals, skipped when it lies beyond the neighbour's normal (the
  neighbour owns that contact);
* pointing toward an end at a concave or straight corner: snapped to n1 and the shape
  clipped against the segment's face, so a box sliding over the joint of two collinear
  segments meets no end corner at all (no snagging).

Circles take the Voronoi regions of the ghost edges directly (Box2D's
b2CollideChainSegmentAndCircle).  Normals point from the segment to the other shape.
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from .manifold import polygon_manifold
from .rounded import round_pair

CONVEX_SINE = 0.01   # a corner turning less than this (sine) counts as flat (Box2D: convexTol)
SKIP_SINE = 0.01     # tolerance of the skip test (Box2D: sinTol)
CHAIN_CIRCLE = 4 << 16


@kernel(forceinline=True)
def _unit(x, y):
    d = math.hypot(x, y)
    return x / d, y / d


@kernel
def chain_circle(v, g, cx, cy, r, margin, out_p, out_s, out_f):
    """Chain segment v (2, 2) with ghosts g (2, 2) against a circle; returns (count, nx, ny)."""
    p1x, p1y, p2x, p2y = v[0, 0], v[0, 1], v[1, 0], v[1, 1]
    ex, ey = p2x - p1x, p2y - p1y
    if ey * (cx - p1x) - ex * (cy - p1y) < 0.0:   # behind: one-sided
        return 0, 0.0, 0.0
    u = ex * (p2x - cx) + ey * (p2y - cy)
    t = ex * (cx - p1x) + ey * (cy - p1y)
    if t <= 0.0:
        if (p1x - g[0, 0]) * (cx - p1x) + (p1y - g[0, 1]) * (cy - p1y) <= 0.0:
            return 0, 0.0, 0.0   # in the previous segment's region
        ax, ay = p1x, p1y
    elif u <= 0.0:
        if (g[1, 0] - p2x) * (cx - p2x) + (g[1, 1] - p2y) * (cy - p2y) > 0.0:
            return 0, 0.0, 0.0   # in the next segment's region
        ax, ay = p2x, p2y
    else:
        ee = ex * ex + ey * ey
        ax = (u * p1x + t * p2x) / ee
        ay = (u * p1y + t * p2y) / ee
    dx, dy = cx - ax, cy - ay
    dist = math.hypot(dx, dy)
    sep = dist - r
    if sep > margin:
        return 0, 0.0, 0.0
    if dist > 0.0:
        nx, ny = dx / dist, dy / dist
    else:
        nx, ny = _unit(ey, -ex)
    out_p[0, 0] = ax + (0.5 * sep) * nx
    out_p[0, 1] = ay + (0.5 * sep) * ny
    out_s[0] = sep
    out_f[0] = CHAIN_CIRCLE
    return 1, nx, ny


@kernel(forceinline=True)
def _classify(nx, ny, e1x, e1y, n0x, n0y, convex1, n2x, n2y, convex2):
    """0 skip, 1 admit, 2 snap to the segment normal (module docstring)."""
    if nx * e1x + ny * e1y <= 0.0:   # toward the tail p1
        if convex1:
            return 0 if nx * n0y - ny * n0x > SKIP_SINE else 1
        return 2
    if convex2:
        return 0 if n2x * ny - n2y * nx > SKIP_SINE else 1
    return 2


@kernel
def chain_polygon(v, nv, g, vb, nb, rb, margin, bias, out_p, out_s, out_f):
    """Chain segment v (2-vertex core, normals nv) with ghosts g against a rounded core vb."""
    e1x, e1y = _unit(v[1, 0] - v[0, 0], v[1, 1] - v[0, 1])
    n1x, n1y = e1y, -e1x
    e0x, e0y = _unit(v[0, 0] - g[0, 0], v[0, 1] - g[0, 1])
    e2x, e2y = _unit(g[1, 0] - v[1, 0], g[1, 1] - v[1, 1])
    convex1 = e0x * e1y - e0y * e1x >= CONVEX_SINE
    convex2 = e1x * e2y - e1y * e2x >= CONVEX_SINE
    cx = 0.0
    cy = 0.0
    for j in range(vb.shape[0]):
        cx += vb[j, 0]
        cy += vb[j, 1]
    cx /= vb.shape[0]
    cy /= vb.shape[0]
    if n1x * (cx - v[0, 0]) + n1y * (cy - v[0, 1]) < 0.0:   # behind: one-sided
        return 0, 0.0, 0.0
    c, nx, ny = round_pair(v, nv, 0.0, vb, nb, rb, margin, bias, out_p, out_s, out_f)
    if c == 0:
        return 0, 0.0, 0.0
    kind = 2 if nx * n1x + ny * n1y < 0.0 else _classify(nx, ny, e1x, e1y, e0y, -e0x, convex1, e2y, -e2x, convex2)
    if kind == 0:
        return 0, 0.0, 0.0
    if kind == 1:
        return c, nx, ny
    # snap: clip the shape against the segment's own face (face 0 of the core: normal n1)
    c, nx, ny = polygon_manifold(v, nv, vb, nb, np.int64(0), np.int64(0), margin + rb, out_p, out_s, out_f)
    shift = -0.5 * rb
    for p in range(c):
        out_s[p] -= rb
        out_p[p, 0] += shift * nx
        out_p[p, 1] += shift * ny
    return c, nx, ny
