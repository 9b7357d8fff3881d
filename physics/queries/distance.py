"""Distances between convex cores: points (1 vertex), segments (2) and CCW polygons (>= 3).

A rounded shape is its core grown by a radius, so two shapes overlap exactly when their
cores are within the sum of the radii.  Two disjoint convex polygons are closest at a vertex
of one and an edge of the other (Ericson, "Real-Time Collision Detection", 9.1 and 5.1.9),
so their distance is the least vertex-to-edge distance; they meet when two edges cross or a
vertex of one lies inside the other.  O(na nb), which is cheap for the <= 64-vertex cores
of this engine and leaves no iteration tolerance to argue about.
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel


@kernel(forceinline=True)
def point_segment(px, py, ax, ay, bx, by):
    """(distance, closest x, closest y) from p to the segment a-b."""
    ex = bx - ax
    ey = by - ay
    ee = ex * ex + ey * ey
    t = 0.0
    if ee > 0.0:
        t = min(max(((px - ax) * ex + (py - ay) * ey) / ee, 0.0), 1.0)
    cx = ax + t * ex
    cy = ay + t * ey
    return math.hypot(px - cx, py - cy), cx, cy


@kernel(forceinline=True)
def core_point_distance(wv, wn, a, k, px, py):
    """Distance from p to the core wv[a:a+k] (0 inside a polygon core; wn: its edge normals)."""
    if k >= 3:
        inside = True
        for i in range(a, a + k):
            if wn[i, 0] * (px - wv[i, 0]) + wn[i, 1] * (py - wv[i, 1]) > 0.0:
                inside = False
                break
        if inside:
            return 0.0
    if k == 1:
        return math.hypot(px - wv[a, 0], py - wv[a, 1])
    best = math.inf
    for i in range(a, a + k):
        j = a if i == a + k - 1 else i + 1
        d, _, _ = point_segment(px, py, wv[i, 0], wv[i, 1], wv[j, 0], wv[j, 1])
        best = min(best, d)
    return best


@kernel(forceinline=True)
def _inside(P, px, py):
    """Is p inside (or on) the CCW polygon P (>= 3 vertices)?"""
    k = P.shape[0]
    for i in range(k):
        j = (i + 1) % k
        if (P[j, 0] - P[i, 0]) * (py - P[i, 1]) - (P[j, 1] - P[i, 1]) * (px - P[i, 0]) < 0.0:
            return False
    return True


@kernel(forceinline=True)
def _cross(ax, ay, bx, by, cx, cy, dx, dy):
    """Do the closed segments a-b and c-d meet (orientation tests)?"""
    d1 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    d2 = (bx - ax) * (dy - ay) - (by - ay) * (dx - ax)
    d3 = (dx - cx) * (ay - cy) - (dy - cy) * (ax - cx)
    d4 = (dx - cx) * (by - cy) - (dy - cy) * (bx - cx)
    return d1 * d2 <= 0.0 and d3 * d4 <= 0.0 and not (d1 == 0.0 and d2 == 0.0 and d3 == 0.0 and d4 == 0.0)


@kernel
def _vertex_edges(P, Q, out, swap):
    """Least distance from a vertex of P to a feature of Q; updates out (d, pa, pb) in place."""
    nq = Q.shape[0]
    for i in range(P.shape[0]):
        for j in range(max(nq if nq > 2 else nq - 1, 1)):
            q2 = (j + 1) % nq
            d, cx, cy = point_segment(P[i, 0], P[i, 1], Q[j, 0], Q[j, 1], Q[q2, 0], Q[q2, 1])
            if d < out[0]:
                out[0] = d
                if swap:
                    out[1], out[2], out[3], out[4] = cx, cy, P[i, 0], P[i, 1]
                else:
                    out[1], out[2], out[3], out[4] = P[i, 0], P[i, 1], cx, cy


@kernel(runtime=True)
def core_distance(P, Q):
    """(distance, pa_x, pa_y, pb_x, pb_y) between the cores P and Q ((k, 2) arrays: 1 = point,
    2 = segment, >= 3 = CCW polygon); 0 when they meet (the witness is then a shared point)."""
    out = np.empty(5)
    out[0] = math.inf
    na = P.shape[0]
    nb = Q.shape[0]
    if nb >= 3 and _inside(Q, P[0, 0], P[0, 1]):
        return 0.0, P[0, 0], P[0, 1], P[0, 0], P[0, 1]
    if na >= 3 and _inside(P, Q[0, 0], Q[0, 1]):
        return 0.0, Q[0, 0], Q[0, 1], Q[0, 0], Q[0, 1]
    if na >= 2 and nb >= 2:
        for i in range(na if na > 2 else 1):
            i2 = (i + 1) % na
            for j in range(nb if nb > 2 else 1):
                j2 = (j + 1) % nb
                if _cross(P[i, 0], P[i, 1], P[i2, 0], P[i2, 1], Q[j, 0], Q[j, 1], Q[j2, 0], Q[j2, 1]):
                    return 0.0, P[i, 0], P[i, 1], P[i, 0], P[i, 1]
    _vertex_edges(P, Q, out, np.bool_(False))  # plain flags: one kernel, not two
    _vertex_edges(Q, P, out, np.bool_(True))
    return out[0], out[1], out[2], out[3], out[4]
