"""Exact ray casts against one fixture's world geometry: circle, polygon, rounded polygon,
capsule, segment and (one-sided) chain segment.

Each returns (fraction, nx, ny) for the ray p + t d, t in [0, 1], or fraction -1 for a miss.
A ray that starts inside a shape hits it at fraction 0 with normal (0, 0) (no surface was
crossed).  The entry of a rounded core is the nearest crossing of its boundary, which is made
of the core's edges pushed out by the radius along their normals and of arcs about the core's
vertices (the Minkowski sum of the core and a disk); taking the nearest hit over all those
pieces is exact, since every piece lies inside the shape (Ericson, "Real-Time Collision
Detection", 5.3.7 for the capsule case).
"""
from __future__ import annotations

import math

from .._jit import kernel
from ..store.fixtures import CHAIN_SEGMENT, CIRCLE
from .distance import core_point_distance

MISS = -1.0


@kernel(forceinline=True)
def ray_circle(cx, cy, r, px, py, dx, dy):
    """Ray against the disk of radius r at (cx, cy): the smaller root of |p + t d - c| = r."""
    mx = px - cx
    my = py - cy
    cc = mx * mx + my * my - r * r
    if cc <= 0.0:
        return 0.0, 0.0, 0.0
    b = mx * dx + my * dy
    dd = dx * dx + dy * dy
    disc = b * b - dd * cc
    if b >= 0.0 or disc < 0.0 or dd == 0.0:
        return MISS, 0.0, 0.0
    t = (-b - math.sqrt(disc)) / dd
    if t > 1.0:
        return MISS, 0.0, 0.0
    t = max(t, 0.0)
    return t, (mx + t * dx) / r, (my + t * dy) / r


@kernel(forceinline=True)
def ray_segment(ax, ay, bx, by, nx, ny, px, py, dx, dy, one_sided):
    """Ray against the segment a-b with unit normal n: the normal returned faces the ray's start
    (one-sided: only rays travelling against n hit, as chain segments are)."""
    ex = bx - ax
    ey = by - ay
    den = dx * ey - dy * ex
    if den == 0.0:
        return MISS, 0.0, 0.0
    qx = ax - px
    qy = ay - py
    t = (qx * ey - qy * ex) / den
    u = (qx * dy - qy * dx) / den
    if t < 0.0 or t > 1.0 or u < 0.0 or u > 1.0:
        return MISS, 0.0, 0.0
    if nx * dx + ny * dy > 0.0:
        if one_sided:
            return MISS, 0.0, 0.0
        return t, -nx, -ny
    return t, nx, ny


@kernel(forceinline=True)
def ray_polygon(wv, wn, a, k, px, py, dx, dy):
    """Ray against a sharp convex polygon by clipping against each edge's half plane
    (Cyrus and Beck 1978): the entry is the largest entering fraction."""
    lo = 0.0
    hi = 1.0
    idx = -1
    for i in range(a, a + k):
        nx = wn[i, 0]
        ny = wn[i, 1]
        num = nx * (wv[i, 0] - px) + ny * (wv[i, 1] - py)
        den = nx * dx + ny * dy
        if den == 0.0:
            if num < 0.0:
                return MISS, 0.0, 0.0
        elif den < 0.0:
            if num < lo * den:
                lo = num / den
                idx = i
        elif num < hi * den:
            hi = num / den
        if hi < lo:
            return MISS, 0.0, 0.0
    if idx < 0:
        return 0.0, 0.0, 0.0
    return lo, wn[idx, 0], wn[idx, 1]


@kernel(forceinline=True)
def ray_rounded(wv, wn, a, k, r, px, py, dx, dy):
    """Ray against a core (k >= 2 vertices) grown by r > 0: nearest hit over pushed-out edges
    and vertex arcs."""
    if core_point_distance(wv, wn, a, k, px, py) <= r:
        return 0.0, 0.0, 0.0
    best = 2.0
    bx = 0.0
    by = 0.0
    for i in range(a, a + k):
        j = a if i == a + k - 1 else i + 1
        nx = wn[i, 0]
        ny = wn[i, 1]
        if nx * dx + ny * dy < 0.0:
            t, hx, hy = ray_segment(wv[i, 0] + r * nx, wv[i, 1] + r * ny, wv[j, 0] + r * nx, wv[j, 1] + r * ny,
                                    nx, ny, px, py, dx, dy, True)
            if t >= 0.0 and t < best:
                best, bx, by = t, hx, hy
        t, hx, hy = ray_circle(wv[i, 0], wv[i, 1], r, px, py, dx, dy)
        if t >= 0.0 and t < best:
            best, bx, by = t, hx, hy
    if best > 1.0:
        return MISS, 0.0, 0.0
    return best, bx, by


@kernel
def ray_fixture(F, wv, wn, wc, f, px, py, dx, dy):
    """(fraction, nx, ny) of the ray p + t d against fixture f's world shape; fraction -1: miss."""
    r = F.radius[f]
    if F.shape[f] == CIRCLE:
        return ray_circle(wc[f, 0], wc[f, 1], r, px, py, dx, dy)
    a = F.vstart[f]
    k = F.vcount[f]
    if r > 0.0:
        return ray_rounded(wv, wn, a, k, r, px, py, dx, dy)
    if k == 2:
        return ray_segment(wv[a, 0], wv[a, 1], wv[a + 1, 0], wv[a + 1, 1], wn[a, 0], wn[a, 1],
                           px, py, dx, dy, F.shape[f] == CHAIN_SEGMENT)
    return ray_polygon(wv, wn, a, k, px, py, dx, dy)
