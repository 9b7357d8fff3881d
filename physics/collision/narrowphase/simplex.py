"""The GJK sub-problem: the point of a simplex (1-3 points) closest to the origin.

Voronoi-region tests with barycentric coordinates in the form of Ericson,
*Real-Time Collision Detection* (2005), sec. 5.1.2 (segment) and 5.1.5
(triangle), with p = origin.  The simplex is reduced in place to the smallest
sub-simplex whose affine hull holds the closest point (van den Bergen 1999,
sec. 4: "the support set"), so the next GJK iteration only ever adds to it.

Kept as calls, not inlined (compile time: _triangle has six segment cases)
and without numba's runtime (no per-array reference counting per call).

Simplex storage (all scratch owned by the caller): ``sw[k]`` = w_k = b - a,
``si[k]`` = (vertex index on a, vertex index on b), ``lam[k]`` = barycentric
weight of w_k in the closest point.
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel


@kernel(forceinline=True)
def _keep(sw, si, lam, dst, src, weight):
    sw[dst, 0] = sw[src, 0]
    sw[dst, 1] = sw[src, 1]
    si[dst, 0] = si[src, 0]
    si[dst, 1] = si[src, 1]
    lam[dst] = weight


@kernel
def _slots():
    """Slot numbers 0, 1, 2 as plain integers: numba compiles a kernel once per literal constant
    it is called with, so ``_segment(..., 0, 1)`` and its five siblings would be six kernels."""
    return np.int64(0), np.int64(1), np.int64(2)


@kernel
def _segment(sw, si, lam, i, j):
    """Closest point on segment w_i w_j; compacts the simplex to slots 0..c-1."""
    ax, ay = sw[i, 0], sw[i, 1]
    ex, ey = sw[j, 0] - ax, sw[j, 1] - ay
    t = -(ax * ex + ay * ey)          # (p - a).e with p = 0
    ee = ex * ex + ey * ey
    if t <= 0.0 or ee == 0.0:
        _keep(sw, si, lam, 0, i, 1.0)
        return 1
    if t >= ee:
        _keep(sw, si, lam, 0, j, 1.0)
        return 1
    t /= ee
    # i < j, so copying i to slot 0 first never overwrites w_j
    _keep(sw, si, lam, 0, i, 1.0 - t)
    _keep(sw, si, lam, 1, j, t)
    return 2


@kernel
def _triangle(sw, si, lam):
    """Closest point on triangle w0 w1 w2 (Ericson 5.1.5 region order)."""
    i0, i1, i2 = _slots()
    ax, ay = sw[0, 0], sw[0, 1]
    abx, aby = sw[1, 0] - ax, sw[1, 1] - ay
    acx, acy = sw[2, 0] - ax, sw[2, 1] - ay
    d1 = -(abx * ax + aby * ay)
    d2 = -(acx * ax + acy * ay)
    if d1 <= 0.0 and d2 <= 0.0:
        return _segment(sw, si, lam, i0, i0)
    bx, by = sw[1, 0], sw[1, 1]
    d3 = -(abx * bx + aby * by)
    d4 = -(acx * bx + acy * by)
    if d3 >= 0.0 and d4 <= d3:
        return _segment(sw, si, lam, i1, i1)
    vc = d1 * d4 - d3 * d2
    if vc <= 0.0 and d1 >= 0.0 and d3 <= 0.0:
        return _segment(sw, si, lam, i0, i1)
    cx, cy = sw[2, 0], sw[2, 1]
    d5 = -(abx * cx + aby * cy)
    d6 = -(acx * cx + acy * cy)
    if d6 >= 0.0 and d5 <= d6:
        return _segment(sw, si, lam, i2, i2)
    vb = d5 * d2 - d1 * d6
    if vb <= 0.0 and d2 >= 0.0 and d6 <= 0.0:
        return _segment(sw, si, lam, i0, i2)
    va = d3 * d6 - d5 * d4
    if va <= 0.0 and d4 - d3 >= 0.0 and d5 - d6 >= 0.0:
        return _segment(sw, si, lam, i1, i2)
    s = va + vb + vc
    if s <= 0.0:  # degenerate (zero-area) triangle: fall back to its edges
        return _segment(sw, si, lam, i0, i1)
    lam[0] = va / s
    lam[1] = vb / s
    lam[2] = vc / s
    return 3


@kernel
def reduce_simplex(sw, si, lam, count):
    """Reduce the simplex to its closest feature; returns (count, vx, vy).

    ``count == 3`` afterwards means the origin lies inside the triangle.
    """
    i0, i1, _ = _slots()
    if count == 1:
        c = _segment(sw, si, lam, i0, i0)
    elif count == 2:
        c = _segment(sw, si, lam, i0, i1)
    else:
        c = _triangle(sw, si, lam)
    if c == 3:
        return 3, 0.0, 0.0
    vx = 0.0
    vy = 0.0
    for k in range(c):
        vx += lam[k] * sw[k, 0]
        vy += lam[k] * sw[k, 1]
    return c, vx, vy
