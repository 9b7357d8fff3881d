"""Polygon-polygon manifolds: reference/incident edges and clipping.

Given the reference face (from SAT or from the GJK/EPA normal), the incident
edge is the edge of the other polygon whose normal is most anti-parallel to
it; clipping it against the two side planes of the reference edge
(Sutherland-Hodgman, one segment against two half-planes) gives up to two
points, so a box lying flat gets an edge-edge contact instead of the seed's
single vertex-edge point (seed 6.1).  See Catto, "Contact manifolds", GDC 2007.

Feature ids: a point names the vertex of A and the vertex of B it stands for (Box2D v3's
b2ClipPolygons), FACE_PAIR | FLIP_BIT (when the reference face is B's) | (vertex of A << 8) |
vertex of B.  Each point stands for one end of the incident edge: its vertex j (the end towards
reference vertex i + 1: the incident edge runs against the reference edge) or j + 1 (towards
reference vertex i).  The point is that incident vertex, or the edge clipped at the reference
edge's side plane there; either way it names the pair (i + 1, j) or (i, j + 1), ordered as (A's,
B's).  A clipped point and the vertex it replaces are one contact: the point moves continuously
as the incident vertex crosses the side plane, and keeps its impulse (collision/narrowphase/
carry.py matches ids).

Where faces of equal length meet (the joints of an arch), the incident vertex lies on the
neighbour's side plane, and rounding decides from step to step whether the point is clipped: an
id that told the two apart dropped both points' impulses each time, and each loss kicked the pile.

A flip of the reference face still changes the id (FLIP_BIT), though the same vertex pair
names the same place (Box2D's ids drop the flip): load stiffening (constraints/
contact_stiffness.py) reads a carried impulse as load, and carried over flips between nearly
parallel faces it toppled a pyramid of small boxes.  The measurements behind both:
bench/results/issue18_experiments.md, "Arch creep".
"""
from __future__ import annotations

from ..._jit import kernel
from .sat import choose_reference, face_separation

FACE_PAIR = 1 << 15  # tags the face points' ids (rounded.py's corner pairs: 3 << 16)
FLIP_BIT = 1 << 14   # set when the reference face is B's


@kernel(forceinline=True)
def incident_edge(vn, nx, ny):
    """The edge of a polygon whose outward normal is most anti-parallel to n."""
    best = 0
    bd = vn[0, 0] * nx + vn[0, 1] * ny
    for j in range(1, vn.shape[0]):
        d = vn[j, 0] * nx + vn[j, 1] * ny
        if d < bd:
            bd = d
            best = j
    return best


@kernel(forceinline=True)
def best_aligned_face(vn, nx, ny):
    """The face of a polygon whose outward normal is closest to n."""
    best = 0
    bd = vn[0, 0] * nx + vn[0, 1] * ny
    for j in range(1, vn.shape[0]):
        d = vn[j, 0] * nx + vn[j, 1] * ny
        if d > bd:
            bd = d
            best = j
    return best


@kernel(forceinline=True)
def reference_from_normal(va, na, vb, nb, nx, ny, bias):
    """(flip, face, separation) from a direction n (A to B), e.g. EPA's or GJK's.

    The candidates are the face of A best aligned with n and the face of B best
    aligned with -n; their exact separations go through the same biased choice
    as SAT, so both methods pick the same reference face.
    """
    fa = best_aligned_face(na, nx, ny)
    fb = best_aligned_face(nb, -nx, -ny)
    sa = face_separation(va, na, fa, vb)
    sb = face_separation(vb, nb, fb, va)
    return choose_reference(sa, fa, sb, fb, bias)


@kernel(forceinline=True)
def _lerp(u1, s1, u2, s2, at):
    """(u, s) on the segment where u == at (u1, u2 on opposite sides of at)."""
    f = (at - u1) / (u2 - u1)
    return at, s1 + f * (s2 - s1)


@kernel(entry=True, forceinline=True)
def clip(vr, nr, i, vi, ni, margin, out_p, out_s, out_f, flip):
    """Clip the incident edge of ``vi`` against reference edge i of ``vr``.

    Writes points midway between the surfaces, separations (along the
    reference normal) and feature ids for points with separation <= margin;
    returns the point count (0, 1 or 2).  Coordinates along the reference
    edge are (u, s): u along its tangent from vertex i, s along its normal.
    """
    nrv = vr.shape[0]
    i2 = i + 1 if i + 1 < nrv else 0
    rx, ry = vr[i, 0], vr[i, 1]
    nx, ny = nr[i, 0], nr[i, 1]
    tx, ty = -ny, nx                     # CCW: tangent = normal turned +90 deg
    length = tx * (vr[i2, 0] - rx) + ty * (vr[i2, 1] - ry)
    j = incident_edge(ni, nx, ny)
    j2 = j + 1 if j + 1 < vi.shape[0] else 0
    u1 = tx * (vi[j, 0] - rx) + ty * (vi[j, 1] - ry)
    s1 = nx * (vi[j, 0] - rx) + ny * (vi[j, 1] - ry)
    u2 = tx * (vi[j2, 0] - rx) + ty * (vi[j2, 1] - ry)
    s2 = nx * (vi[j2, 0] - rx) + ny * (vi[j2, 1] - ry)
    k1, k2 = 0, 1
    n_pts = 2
    # side plane u >= 0 at reference vertex i
    if u1 < 0.0 and u2 < 0.0:      # incident edge wholly beside the face:
        n_pts = 1                  # keep its nearer vertex (speculative case)
        if u2 > u1:
            u1, s1, k1 = u2, s2, k2
    elif u1 < 0.0:
        u1, s1 = _lerp(u1, s1, u2, s2, 0.0)
    elif u2 < 0.0:
        u2, s2 = _lerp(u1, s1, u2, s2, 0.0)
    # side plane u <= length at reference vertex i + 1
    if n_pts == 2:
        if u1 > length and u2 > length:
            n_pts = 1
            if u2 < u1:
                u1, s1, k1 = u2, s2, k2
        elif u1 > length:
            u1, s1 = _lerp(u1, s1, u2, s2, length)
        elif u2 > length:
            u2, s2 = _lerp(u1, s1, u2, s2, length)
    c = 0
    for p in range(n_pts):
        u, s, k = (u1, s1, k1) if p == 0 else (u2, s2, k2)
        if s > margin:
            continue
        vi_k = j if k == 0 else j2       # the incident vertex the point stands for
        vr_k = i2 if k == 0 else i       # and the reference vertex across from it
        ida, idb = (vi_k, vr_k) if flip else (vr_k, vi_k)
        h = 0.5 * s                      # midway between the two surfaces
        out_p[c, 0] = rx + u * tx + h * nx
        out_p[c, 1] = ry + u * ty + h * ny
        out_s[c] = s
        out_f[c] = FACE_PAIR | (flip * FLIP_BIT) | (ida << 8) | idb
        c += 1
    return c


@kernel
def polygon_manifold(va, na, vb, nb, flip, face, margin, out_p, out_s, out_f):
    """Manifold for a chosen reference face; returns (count, nx, ny), n from A to B."""
    # one clip call site for both roles: it is the biggest inlined kernel
    if flip:
        vr, nr, vi, ni, sign = vb, nb, va, na, -1.0
    else:
        vr, nr, vi, ni, sign = va, na, vb, nb, 1.0
    c = clip(vr, nr, face, vi, ni, margin, out_p, out_s, out_f, flip)
    return c, sign * nr[face, 0], sign * nr[face, 1]
