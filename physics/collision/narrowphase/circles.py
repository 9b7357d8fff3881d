"""Closed-form contacts involving circles: circle-circle and polygon-circle.

Both give one point midway between the surfaces.  Feature ids: circle-circle
is 1 << 16; polygon-circle is (2 << 16) | (region << 8) | index with region 0
for a face (the centre projects onto edge ``index``) and 1 for a vertex.
"""
from __future__ import annotations

import math

from ..._jit import kernel

CIRCLE_CIRCLE = 1 << 16
POLY_CIRCLE = 2 << 16


@kernel(entry=True, forceinline=True)
def circle_circle(ax, ay, ra, bx, by, rb, margin, out_p, out_s, out_f):
    """Returns (count, nx, ny); n from A to B.

    Coincident centres have no direction; +y is as good as any and keeps the
    result finite (the solver then pushes the circles apart vertically).
    """
    dx = bx - ax
    dy = by - ay
    dist = math.hypot(dx, dy)
    sep = dist - ra - rb
    if sep > margin:
        return 0, 0.0, 0.0
    if dist > 1e-12 * (ra + rb):
        nx, ny = dx / dist, dy / dist
    else:
        nx, ny = 0.0, 1.0
    h = ra + 0.5 * sep
    out_p[0, 0] = ax + h * nx
    out_p[0, 1] = ay + h * ny
    out_s[0] = sep
    out_f[0] = CIRCLE_CIRCLE
    return 1, nx, ny


@kernel(entry=True)
def polygon_circle(v, vn, cx, cy, r, margin, out_p, out_s, out_f):
    """Polygon A against circle B; returns (count, nx, ny), n from A to B.

    The face of greatest separation of the centre decides (for a convex
    polygon its Voronoi regions are the face slab and its two end vertices'
    wedges; Ericson 2005, sec. 5.1.2).  A centre inside uses that face's
    normal: it is the direction of least penetration.
    """
    n = v.shape[0]
    best = 0
    bs = -math.inf
    for i in range(n):
        s = vn[i, 0] * (cx - v[i, 0]) + vn[i, 1] * (cy - v[i, 1])
        if s > bs:
            bs = s
            best = i
    if bs - r > margin:
        return 0, 0.0, 0.0
    i2 = best + 1 if best + 1 < n else 0
    nx, ny = vn[best, 0], vn[best, 1]
    sep = bs - r
    feat = POLY_CIRCLE | best
    if bs > 0.0:
        ex = v[i2, 0] - v[best, 0]
        ey = v[i2, 1] - v[best, 1]
        corner = -1
        if (cx - v[best, 0]) * ex + (cy - v[best, 1]) * ey <= 0.0:
            corner = best
        elif (cx - v[i2, 0]) * ex + (cy - v[i2, 1]) * ey >= 0.0:
            corner = i2
        if corner >= 0:
            dx = cx - v[corner, 0]
            dy = cy - v[corner, 1]
            dist = math.hypot(dx, dy)   # >= bs > 0: the centre is outside
            sep = dist - r
            if sep > margin:
                return 0, 0.0, 0.0
            nx, ny = dx / dist, dy / dist
            feat = POLY_CIRCLE | (1 << 8) | corner
    h = r + 0.5 * sep
    out_p[0, 0] = cx - h * nx
    out_p[0, 1] = cy - h * ny
    out_s[0] = sep
    out_f[0] = feat
    return 1, nx, ny
