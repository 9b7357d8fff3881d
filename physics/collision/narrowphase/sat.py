"""Separating-axis test over the face normals of two convex polygons (seed 4.1.1).

For convex polygons the candidate axes are the edge normals of both
(Gottschalk et al. 1996; Ericson 2005, sec. 4.4).  Along the outward normal
n_i of edge i of A, the separation of B from that face is
s_i = min_j n_i.(b_j - a_i): positive means a separating axis, and the largest
s over all faces of A and B is minus the minimum overlap, i.e. minus the
penetration depth EPA finds (each face of M = B - A is a face of A or of B).
"""
from __future__ import annotations

from ..._jit import kernel


@kernel(forceinline=True)
def face_separation(va, na, i, vb):
    """s_i = min_j n_i.(b_j - a_i) for face i of A against all vertices of B."""
    nx = na[i, 0]
    ny = na[i, 1]
    px = va[i, 0]
    py = va[i, 1]
    s = nx * (vb[0, 0] - px) + ny * (vb[0, 1] - py)
    for j in range(1, vb.shape[0]):
        d = nx * (vb[j, 0] - px) + ny * (vb[j, 1] - py)
        if d < s:
            s = d
    return s


@kernel(forceinline=True)
def max_separation(va, na, vb):
    """(separation, face) of A's face that best separates B (O(n m))."""
    best = 0
    bs = face_separation(va, na, 0, vb)
    for i in range(1, va.shape[0]):
        s = face_separation(va, na, i, vb)
        if s > bs:
            bs = s
            best = i
    return bs, best


@kernel(forceinline=True)
def choose_reference(sa, fa, sb, fb, bias):
    """(flip, face, separation): B's face is the reference only if clearly better.

    The bias (a fraction of the shapes' size) keeps the reference face from
    flipping between A and B when both give nearly the same separation, as
    for a box resting flat on another: a flip would change every feature id
    and lose the warm start (Catto, Box2D's b2CollidePolygons, same idea).
    """
    if sb > sa + bias:
        return 1, fb, sb
    return 0, fa, sa


@kernel(entry=True)
def sat_query(va, na, vb, nb):
    """Test entry: (separation, nx, ny, face, flip), no bias.

    separation = max face separation (= -penetration depth when overlapping);
    n is the unit normal of the best face, oriented from A to B; flip = 1 when
    that face belongs to B.
    """
    sa, fa = max_separation(va, na, vb)
    sb, fb = max_separation(vb, nb, va)
    flip, face, sep = choose_reference(sa, fa, sb, fb, 0.0)
    if flip:
        return sep, -nb[face, 0], -nb[face, 1], face, flip
    return sep, na[face, 0], na[face, 1], face, flip
