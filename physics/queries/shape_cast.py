"""Shape casts: the first fixture a rounded core meets when translated along a vector.

For a pure translation, the distance g(t) = dist(A + t T, B) - (ra + rb) between convex
shapes is convex in t, and g'(t) = n . T with n the unit direction from B's closest point to
A's (the envelope theorem).  Newton's step t -= g / g' from below therefore never passes the
first root (a convex function lies above its tangents), so it is a root finder without a
bracket or overshoot; for sharp polygons g is piecewise linear and Newton lands on the root
in a few steps.  If g' >= 0 the shapes never get closer: no hit (cf. conservative
advancement, Mirtich 1996, and Box2D v3's b2ShapeCast, which iterates the same idea with GJK).
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel
from .distance import core_distance
from .region import box_candidates, core_of

#: stop within this gap (m): far below the engine's linear slop (5 mm), above rounding noise
TOLERANCE = 1e-9
MAX_ITERATIONS = 64


@kernel(runtime=True)
def cast_against(P, rp, tx, ty, Q, rq):
    """(fraction, point x, y, normal x, y) of core P (radius rp) moved by t (tx, ty) against Q
    (radius rq); fraction -1 for no contact within t in [0, 1].  The point is on Q's surface and
    the normal points from Q toward the cast shape; a start in contact gives 0 and normal (0, 0)."""
    moved = P.copy()
    t = 0.0
    nx = 0.0
    ny = 0.0
    for _ in range(MAX_ITERATIONS):
        for i in range(P.shape[0]):
            moved[i, 0] = P[i, 0] + t * tx
            moved[i, 1] = P[i, 1] + t * ty
        d, ax, ay, bx, by = core_distance(moved, Q)
        g = d - rp - rq
        if d > 0.0:
            nx = (ax - bx) / d
            ny = (ay - by) / d
        if g <= TOLERANCE:
            if t == 0.0:
                return 0.0, bx + rq * nx, by + rq * ny, 0.0, 0.0
            return t, bx + rq * nx, by + rq * ny, nx, ny
        slope = nx * tx + ny * ty
        if slope >= 0.0:
            return -1.0, 0.0, 0.0, 0.0, 0.0
        t -= g / slope
        if t > 1.0:
            return -1.0, 0.0, 0.0, 0.0, 0.0
    return -1.0, 0.0, 0.0, 0.0, 0.0


@kernel(entry=True, runtime=True)
def shape_cast(F, wv, wc, box, nb, info, order, P, rp, tx, ty, category, mask, out, hit):
    """The first fixture (slot, or -1) the swept core meets; hit[:] = fraction, point, normal."""
    x0 = min(P[:, 0].min(), P[:, 0].min() + tx) - rp
    y0 = min(P[:, 1].min(), P[:, 1].min() + ty) - rp
    x1 = max(P[:, 0].max(), P[:, 0].max() + tx) + rp
    y1 = max(P[:, 1].max(), P[:, 1].max() + ty) + rp
    m = box_candidates(F, box, nb, info, order, x0, y0, x1, y1, category, mask, out)
    best = -1
    hit[0] = math.inf
    for j in range(m):
        f = out[j]
        t, px, py, nx, ny = cast_against(P, rp, tx, ty, core_of(F, wv, wc, f), F.radius[f])
        if t < 0.0 or t > hit[0] or (t == hit[0] and f > best):
            continue
        best = f
        hit[0], hit[1], hit[2], hit[3], hit[4] = t, px, py, nx, ny
    return best
