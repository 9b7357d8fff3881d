"""Support mappings of convex polygons and their Minkowski difference.

GJK and EPA see a shape only through its support function
s_A(d) = argmax_{p in A} d.p (van den Bergen 1999, sec. 2).  The
configuration-space obstacle is M = B - A, whose support is
s_M(d) = s_B(d) - s_A(-d); M contains the origin iff A and B overlap, and a
point w of M closest to the origin is p_b - p_a for the closest points.
"""
from __future__ import annotations

from ..._jit import kernel


@kernel(forceinline=True)
def support_index(v, dx, dy):
    """Index of the vertex of ``v`` farthest along (dx, dy); first one wins ties."""
    best = 0
    bd = v[0, 0] * dx + v[0, 1] * dy
    for i in range(1, v.shape[0]):
        d = v[i, 0] * dx + v[i, 1] * dy
        if d > bd:
            bd = d
            best = i
    return best


@kernel(forceinline=True)
def extent(va, vb):
    """A length scale of the pair: the largest |coordinate| of either polygon.

    Tolerances are relative to it so that the tests mean the same thing for
    shapes of 1 cm and of 100 m (callers shift coordinates next to the pair).
    """
    s = 0.0
    for i in range(va.shape[0]):
        s = max(s, abs(va[i, 0]), abs(va[i, 1]))
    for i in range(vb.shape[0]):
        s = max(s, abs(vb[i, 0]), abs(vb[i, 1]))
    return s
