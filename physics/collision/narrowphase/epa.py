"""EPA: penetration depth and direction of overlapping polygons (seed 3.1).

The expanding polytope algorithm (van den Bergen 2001, "Proximity queries and
penetration depth computation on 3D game objects"; here in 2D) grows a polygon
inscribed in M = B - A from GJK's final simplex: take the edge nearest the
origin, add the support point of M along its outward normal, stop when that
point lies on the edge (within tolerance).  The edge then is a face of M, its
outward normal n_M is minus the contact normal (A to B), and its distance d
from the origin is the penetration depth: translating B by -d n_M makes the
shapes touch.

The polytope is kept counter-clockwise so an edge's outward normal is its
direction turned by -90 degrees: it is well defined even when the origin lies
on the edge (touching), which is where a normalised "origin to closest point"
direction would be 0/0.  Distances are signed, so an origin a rounding error
outside the start polytope still gives the right face.
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from .gjk import gjk
from .support import extent, support_index

EPA_EPS = 1e-12      # relative stop tolerance on the support-point gain


@kernel(forceinline=True)
def _support_w(va, vb, dx, dy):
    ia = support_index(va, -dx, -dy)
    ib = support_index(vb, dx, dy)
    return vb[ib, 0] - va[ia, 0], vb[ib, 1] - va[ia, 1]


@kernel(forceinline=True)
def _far_from_line(va, vb, ax, ay, bx, by, tol):
    """A support point of M off the line through a, b (both sides tried)."""
    px, py = -(by - ay), bx - ax
    best_x, best_y, best_h = bx, by, -1.0
    for sgn in (1.0, -1.0):
        wx, wy = _support_w(va, vb, sgn * px, sgn * py)
        h = abs(px * (wx - ax) + py * (wy - ay))
        if h > best_h:
            best_x, best_y, best_h = wx, wy, h
    return best_x, best_y


@kernel
def start_polytope(va, vb, sw, count, poly, tol):
    """Grow GJK's simplex (origin inside or on it) into a CCW triangle in ``poly``.

    A touching contact ends GJK with a point or a segment; M has area (both
    polygons do), so supports perpendicular to it give a proper triangle.
    """
    ax, ay = sw[0, 0], sw[0, 1]
    if count >= 2:
        bx, by = sw[1, 0], sw[1, 1]
    else:
        bx, by = _support_w(va, vb, 1.0, 0.0)
        if abs(bx - ax) + abs(by - ay) <= tol:
            bx, by = _support_w(va, vb, -1.0, 0.0)
    if count == 3:
        cx, cy = sw[2, 0], sw[2, 1]
    else:
        cx, cy = _far_from_line(va, vb, ax, ay, bx, by, tol)
    poly[0, 0], poly[0, 1] = ax, ay
    if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) >= 0.0:
        poly[1, 0], poly[1, 1], poly[2, 0], poly[2, 1] = bx, by, cx, cy
    else:
        poly[1, 0], poly[1, 1], poly[2, 0], poly[2, 1] = cx, cy, bx, by
    return np.int64(3)  # not a literal 3: expand compiles once


@kernel(forceinline=True)
def _nearest_edge(poly, n):
    """(index, distance, nx, ny) of the CCW edge nearest the origin."""
    best = -1
    bd = math.inf
    bnx = 0.0
    bny = 1.0
    for i in range(n):
        j = i + 1 if i + 1 < n else 0
        ex = poly[j, 0] - poly[i, 0]
        ey = poly[j, 1] - poly[i, 1]
        ln = math.hypot(ex, ey)
        if ln == 0.0:
            continue
        nx = ey / ln
        ny = -ex / ln
        d = nx * poly[i, 0] + ny * poly[i, 1]
        if d < bd:
            best, bd, bnx, bny = i, d, nx, ny
    return best, bd, bnx, bny


@kernel(entry=True)
def expand(va, vb, poly, n, tol):
    """Run EPA from the CCW polytope poly[:n]; returns (depth, nx, ny)."""
    cap = poly.shape[0]
    depth, nx, ny = 0.0, 0.0, 1.0
    while True:
        i, depth, nx, ny = _nearest_edge(poly, n)
        if i < 0:  # every edge degenerate: cannot happen for polygons with area
            return 0.0, 0.0, 1.0
        wx, wy = _support_w(va, vb, nx, ny)
        if nx * wx + ny * wy - depth <= tol or n == cap:
            return depth, nx, ny
        for k in range(n, i + 1, -1):  # insert w after vertex i
            poly[k, 0] = poly[k - 1, 0]
            poly[k, 1] = poly[k - 1, 1]
        poly[i + 1, 0] = wx
        poly[i + 1, 1] = wy
        n += 1


@kernel(entry=True)
def penetration(va, vb, sw, si, lam, poly):
    """GJK, then EPA when overlapping; returns (separation, nx, ny).

    separation > 0: distance, n the closest-points direction; separation <= 0:
    minus the penetration depth, n the EPA face normal.  n is from A to B.
    """
    count, dist, vx, vy = gjk(va, vb, sw, si, lam)
    if dist > 0.0:
        return dist, vx / dist, vy / dist
    scale = max(extent(va, vb), 1e-300)
    n = start_polytope(va, vb, sw, count, poly, 1e-10 * scale)
    depth, nx, ny = expand(va, vb, poly, n, EPA_EPS * scale)
    # M's outward normal at the face points from B towards A (translating B
    # by -depth * n_M moves M off the origin), so the A-to-B normal is -n_M
    return -depth, -nx, -ny


@kernel(entry=True, runtime=True)
def epa(va, vb):
    """Test entry: (depth, nx, ny); depth < 0 is the distance of apart shapes."""
    sw = np.empty((3, 2))
    si = np.empty((3, 2), np.int64)
    lam = np.empty(3)
    poly = np.empty((va.shape[0] + vb.shape[0] + 4, 2))
    sep, nx, ny = penetration(va, vb, sw, si, lam, poly)
    return -sep, nx, ny
