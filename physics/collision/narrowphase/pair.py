"""One polygon pair, by either method: the reference face, then the manifold.

SAT (seed 4.1.1) finds the reference face directly.  GJK (seed 4.1.2) gives
the exact distance of apart shapes, EPA (seed 3.1) the penetration normal of
overlapping ones; the reference face is the one aligned with that normal.
Both end in the same clipping step, so they give the same manifold whenever
they pick the same face (always, except for near-ties within the bias).

``sat_pair``, ``polygon_pair`` and ``polygon_manifold`` (manifold.py) are functions of their own,
called with plain arrays, not inlined into the narrow phase's pair loop: numba's IR inliner
types a callee again at every call site and every level of nesting, and these three sit above
the clipping and the separation helpers.  The leaf helpers below them stay inlined.
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel
from ...options import NARROWPHASES
from .epa import penetration
from .manifold import polygon_manifold, reference_from_normal
from .sat import choose_reference, max_separation

SAT, GJK = 0, 1
METHODS = {name: NARROWPHASES.index(name) for name in NARROWPHASES}
assert METHODS == {"sat": SAT, "gjk": GJK}


@kernel
def sat_pair(va, na, vb, nb, margin, bias, out_p, out_s, out_f):
    """One polygon pair by SAT alone (the lean narrow kernel's, and ``polygon_pair``'s for SAT
    and for the GJK cases SAT settles): returns (count, nx, ny); count 0 when the pair is apart
    beyond ``margin``."""
    sa, fa = max_separation(va, na, vb)
    if sa > margin:
        return 0, 0.0, 0.0
    sb, fb = max_separation(vb, nb, va)
    if sb > margin:
        return 0, 0.0, 0.0
    flip, face, _ = choose_reference(sa, fa, sb, fb, bias)
    return polygon_manifold(va, na, vb, nb, np.int64(flip), np.int64(face), margin, out_p, out_s, out_f)


@kernel
def polygon_pair(va, na, vb, nb, method, margin, bias, sw, si, lam, poly, out_p, out_s, out_f):
    """Returns (count, nx, ny); count 0 when the pair is apart beyond ``margin``."""
    if method == GJK:
        sep, nx, ny = penetration(va, vb, sw, si, lam, poly)
        if sep > margin:
            return 0, 0.0, 0.0
        flip, face, s = reference_from_normal(va, na, vb, nb, nx, ny, bias)
        # apart shapes whose closest features are two vertices: the faces next
        # to n need not separate (a long sliver reaching past a corner); the
        # manifold then needs a face that does, which SAT finds
        if not (sep > 0.0 and s < 0.0):
            return polygon_manifold(va, na, vb, nb, np.int64(flip), np.int64(face), margin, out_p, out_s, out_f)
    return sat_pair(va, na, vb, nb, margin, bias, out_p, out_s, out_f)


@kernel(entry=True, runtime=True)
def polygon_collide(va, na, vb, nb, method, margin, bias):
    """Test entry: (count, nx, ny, points (2,2), separations (2,), features (2,))."""
    sw = np.empty((3, 2))
    si = np.empty((3, 2), np.int64)
    lam = np.empty(3)
    poly = np.empty((va.shape[0] + vb.shape[0] + 4, 2))
    out_p = np.zeros((2, 2))
    out_s = np.zeros(2)
    out_f = np.zeros(2, np.int32)
    c, nx, ny = polygon_pair(va, na, vb, nb, method, margin, bias, sw, si, lam, poly,
                             out_p, out_s, out_f)
    return c, nx, ny, out_p, out_s, out_f
