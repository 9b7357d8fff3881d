"""Rounded cores: polygons with a radius, capsules (two-vertex rounded cores) and segments.

Box2D v3 treats every such shape as a convex core swept by a disc (b2Polygon with a radius,
b2MakeCapsule), so one routine covers every pair of them.  The surfaces are the cores
pushed out by their radii, so the separation of two shapes is the distance of their cores
minus ra + rb, along the direction between the cores' closest points.

* Apart cores: the exact core distance is the smallest vertex-to-edge distance (in 2D the
  closest features of two disjoint convex sets always include a vertex of one of them;
  Ericson 2005, sec. 5.1.9).  Face contacts (parallel edges, a corner on a face) are clipped
  as for sharp polygons (manifold.py) and keep their two points; when the clipped separation
  disagrees with the true one, the closest features are two corners (or an end cap) and the
  contact is one point along the line between them (Box2D's b2CollidePolygons makes the
  same vertex-vertex check).
* Overlapping cores: the separating-axis face of least penetration, clipped (manifold.py).

Every point lies midway between the two rounded surfaces; separations are those of the
surfaces (core separation minus ra + rb).  Feature ids: clipped points keep manifold.py's
(FACE_PAIR | (i << 8) | j); a corner pair is (3 << 16) | (i << 8) | j (i on A, j on B).
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from .manifold import polygon_manifold
from .sat import choose_reference, max_separation

CORNER_PAIR = 3 << 16


@kernel(forceinline=True)
def _point_segment(px, py, ax, ay, bx, by):
    """(squared distance, t) of point p to segment a-b, t in [0, 1] along it."""
    ex = bx - ax
    ey = by - ay
    ee = ex * ex + ey * ey
    t = 0.0
    if ee > 0.0:
        t = min(1.0, max(0.0, ((px - ax) * ex + (py - ay) * ey) / ee))
    dx = px - (ax + t * ex)
    dy = py - (ay + t * ey)
    return dx * dx + dy * dy, t


@kernel(forceinline=True)
def _vertex_edges(vp, ve):
    """Closest pair (d2, vertex index, edge index, t) of a vertex of vp to an edge of ve."""
    best = math.inf
    bi = 0
    bj = 0
    bt = 0.0
    m = ve.shape[0]
    edges = m if m > 2 else 1   # a two-vertex core has one edge (listed twice)
    for i in range(vp.shape[0]):
        for j in range(edges):
            j2 = j + 1 if j + 1 < m else 0
            d2, t = _point_segment(vp[i, 0], vp[i, 1], ve[j, 0], ve[j, 1], ve[j2, 0], ve[j2, 1])
            if d2 < best:
                best, bi, bj, bt = d2, i, j, t
    return best, bi, bj, bt


@kernel(forceinline=True)
def _orient(ax, ay, bx, by, cx, cy):
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


@kernel(forceinline=True)
def _inside(v, n, px, py):
    """Is p inside (or on) the convex core v with outward normals n (three or more vertices)?"""
    if v.shape[0] < 3:
        return False
    for i in range(v.shape[0]):
        if n[i, 0] * (px - v[i, 0]) + n[i, 1] * (py - v[i, 1]) > 0.0:
            return False
    return True


@kernel(forceinline=True)
def cores_overlap(va, na, vb, nb):
    """Do the two convex cores intersect? (a vertex inside the other, or two edges crossing)"""
    for i in range(va.shape[0]):
        if _inside(vb, nb, va[i, 0], va[i, 1]):
            return True
    for j in range(vb.shape[0]):
        if _inside(va, na, vb[j, 0], vb[j, 1]):
            return True
    n, m = va.shape[0], vb.shape[0]
    for i in range(n):
        i2 = i + 1 if i + 1 < n else 0
        for j in range(m):
            j2 = j + 1 if j + 1 < m else 0
            d1 = _orient(va[i, 0], va[i, 1], va[i2, 0], va[i2, 1], vb[j, 0], vb[j, 1])
            d2 = _orient(va[i, 0], va[i, 1], va[i2, 0], va[i2, 1], vb[j2, 0], vb[j2, 1])
            d3 = _orient(vb[j, 0], vb[j, 1], vb[j2, 0], vb[j2, 1], va[i, 0], va[i, 1])
            d4 = _orient(vb[j, 0], vb[j, 1], vb[j2, 0], vb[j2, 1], va[i2, 0], va[i2, 1])
            if ((d1 > 0.0) != (d2 > 0.0)) and ((d3 > 0.0) != (d4 > 0.0)):
                return True
    return False


@kernel(forceinline=True)
def core_distance(va, vb):
    """(distance, pax, pay, pbx, pby, ia, ib): the closest points of two disjoint cores and
    the vertex or edge index on each that made them."""
    d2a, ia, jb, ta = _vertex_edges(va, vb)
    d2b, ib, ja, tb = _vertex_edges(vb, va)
    m = vb.shape[0]
    n = va.shape[0]
    if d2a <= d2b:
        j2 = jb + 1 if jb + 1 < m else 0
        qx = vb[jb, 0] + ta * (vb[j2, 0] - vb[jb, 0])
        qy = vb[jb, 1] + ta * (vb[j2, 1] - vb[jb, 1])
        return math.sqrt(d2a), va[ia, 0], va[ia, 1], qx, qy, ia, jb
    j2 = ja + 1 if ja + 1 < n else 0
    px = va[ja, 0] + tb * (va[j2, 0] - va[ja, 0])
    py = va[ja, 1] + tb * (va[j2, 1] - va[ja, 1])
    return math.sqrt(d2b), px, py, vb[ib, 0], vb[ib, 1], ja, ib


@kernel
def round_pair(va, na, ra, vb, nb, rb, margin, bias, out_p, out_s, out_f):
    """Manifold of two rounded cores (module docstring); returns (count, nx, ny), n from A to B."""
    rsum = ra + rb
    overlap = cores_overlap(va, na, vb, nb)
    d = 0.0
    if not overlap:
        d, pax, pay, pbx, pby, ia, ib = core_distance(va, vb)
        if d - rsum > margin:
            return 0, 0.0, 0.0
    sa, fa = max_separation(va, na, vb)
    sb, fb = max_separation(vb, nb, va)
    flip, face, _ = choose_reference(sa, fa, sb, fb, bias)
    c, nx, ny = polygon_manifold(va, na, vb, nb, np.int64(flip), np.int64(face), margin + rsum, out_p, out_s, out_f)
    shift = 0.5 * (ra - rb)       # the midpoint of the rounded surfaces, not of the cores
    lo = math.inf
    for p in range(c):
        out_s[p] -= rsum
        out_p[p, 0] += shift * nx
        out_p[p, 1] += shift * ny
        lo = min(lo, out_s[p])
    tol = max(bias, 1e-9)
    if overlap or d <= tol or (c > 0 and abs(lo - (d - rsum)) <= tol):
        return c, nx, ny
    # the faces do not carry the contact: the closest features are corners (or an end cap)
    nx = (pbx - pax) / d
    ny = (pby - pay) / d
    sep = d - rsum
    h = ra + 0.5 * sep
    out_p[0, 0] = pax + h * nx
    out_p[0, 1] = pay + h * ny
    out_s[0] = sep
    out_f[0] = CORNER_PAIR | (ia << 8) | ib
    return 1, nx, ny
