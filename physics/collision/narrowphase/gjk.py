"""GJK distance between two convex polygons (van den Bergen 1999).

Iterates on the Minkowski difference M = B - A: keep a simplex of support
points, find its point v closest to the origin, add the support point of M in
direction -v, until no support point gets closer (sec. 3, the termination
test |v|^2 - v.w <= eps |v|^2) or the origin is enclosed (overlap).  For
polygons M has finitely many vertices, so a repeated support point (same
vertex pair) is an exact stop as well.
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from .simplex import reduce_simplex
from .support import extent, support_index

MAX_ITERS = 160      # > 2 * 64 vertices: M never has more vertices than that
REL_EPS = 1e-12      # relative tolerance of the termination test (sec. 3.2)
TOUCH_EPS = 1e-10    # |v| below TOUCH_EPS * extent counts as touching


@kernel(forceinline=True)
def _add_support(va, vb, sw, si, k, dx, dy):
    """Put the support point of M in direction (dx, dy) into simplex slot k."""
    ia = support_index(va, -dx, -dy)
    ib = support_index(vb, dx, dy)
    sw[k, 0] = vb[ib, 0] - va[ia, 0]
    sw[k, 1] = vb[ib, 1] - va[ia, 1]
    si[k, 0] = ia
    si[k, 1] = ib


@kernel
def gjk(va, vb, sw, si, lam):
    """Distance from A to B; returns (count, distance, vx, vy).

    v = p_b - p_a is the closest point of M (so v/|v| is the normal from A to
    B); distance 0 means overlap or touching, and the simplex left in
    (sw, si, lam, count) is EPA's starting polytope.
    """
    tol = TOUCH_EPS * max(extent(va, vb), 1e-300)
    # start along the line between the first vertices; any direction works
    dx = vb[0, 0] - va[0, 0]
    dy = vb[0, 1] - va[0, 1]
    if dx == 0.0 and dy == 0.0:
        dx = 1.0
    _add_support(va, vb, sw, si, 0, dx, dy)
    count = np.int64(1)  # not a literal: reduce_simplex compiles once (simplex.py: _slots)
    vx = sw[0, 0]
    vy = sw[0, 1]
    for _ in range(MAX_ITERS):
        count, vx, vy = reduce_simplex(sw, si, lam, count)
        if count == 3:
            return 3, 0.0, 0.0, 0.0
        vv = vx * vx + vy * vy
        if vv <= tol * tol:
            return count, 0.0, vx, vy
        _add_support(va, vb, sw, si, count, -vx, -vy)
        for k in range(count):  # repeated vertex pair: v is already optimal
            if si[k, 0] == si[count, 0] and si[k, 1] == si[count, 1]:
                return count, math.sqrt(vv), vx, vy
        if vv - (vx * sw[count, 0] + vy * sw[count, 1]) <= REL_EPS * vv:
            return count, math.sqrt(vv), vx, vy
        count += 1
    return count, math.sqrt(vx * vx + vy * vy), vx, vy


@kernel
def closest_points(va, vb, si, lam, count):
    """The witness points p_a, p_b of the last GJK call (barycentric sums)."""
    pax = pay = pbx = pby = 0.0
    for k in range(count):
        pax += lam[k] * va[si[k, 0], 0]
        pay += lam[k] * va[si[k, 0], 1]
        pbx += lam[k] * vb[si[k, 1], 0]
        pby += lam[k] * vb[si[k, 1], 1]
    return pax, pay, pbx, pby


@kernel(entry=True, runtime=True)
def gjk_distance(va, vb):
    """Test entry: (distance, nx, ny, pax, pay, pbx, pby) for two polygons.

    n is the unit normal from A to B when apart, (0, 0) when overlapping.
    Allocates its own scratch; the pipeline calls ``gjk`` with preallocated
    arrays instead.
    """
    sw = np.empty((3, 2))
    si = np.empty((3, 2), np.int64)
    lam = np.empty(3)
    count, dist, vx, vy = gjk(va, vb, sw, si, lam)
    nx = ny = 0.0
    if dist > 0.0:
        nx = vx / dist
        ny = vy / dist
    if count == 3:
        return dist, nx, ny, math.nan, math.nan, math.nan, math.nan
    pax, pay, pbx, pby = closest_points(va, vb, si, lam, count)
    return dist, nx, ny, pax, pay, pbx, pby
