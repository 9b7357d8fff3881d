"""Property tests of the single-pair narrow-phase queries: SAT, GJK, EPA, manifolds.

Random convex polygons (hulls of random points, regular polygons, boxes,
slivers) in random poses, at random scales; every check is relative to the
pair's size so the same tolerances hold from 1 cm to 100 m.
"""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from physics.collision.narrowphase import (GJK, SAT, circle_circle, epa, gjk_distance, polygon_circle,
                                 polygon_collide, sat_query)
from physics.geometry.shapes import Polygon

SETTINGS = dict(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much,
                                                               HealthCheck.data_too_large])


# -- shapes ------------------------------------------------------------------
@st.composite
def polygons(draw):
    kind = draw(st.sampled_from(["hull", "regular", "box", "sliver"]))
    if kind == "hull":
        n = draw(st.integers(3, 16))
        pts = draw(st.lists(st.tuples(st.floats(-1, 1), st.floats(-1, 1)), min_size=n, max_size=n))
        try:
            poly = Polygon.hull(pts)
        except ValueError:
            assume(False)
        # very thin hulls are covered by "sliver"; keep these well-shaped
        assume(poly.area > 0.05)
        return poly
    if kind == "regular":
        return Polygon.regular(draw(st.integers(3, 16)), draw(st.floats(0.2, 1.5)))
    if kind == "box":
        return Polygon.box(draw(st.floats(0.2, 2.0)), draw(st.floats(0.2, 2.0)))
    return Polygon.box(draw(st.floats(1.0, 2.0)), draw(st.floats(1e-3, 2e-3)))


def place(poly, x, y, angle, scale=1.0):
    """World vertices and outward edge normals of ``poly`` scaled, rotated, moved."""
    c, s = math.cos(angle), math.sin(angle)
    v = (poly.vertices - poly.centroid) * scale
    w = np.column_stack([c * v[:, 0] - s * v[:, 1] + x, s * v[:, 0] + c * v[:, 1] + y])
    e = np.roll(w, -1, axis=0) - w
    nrm = np.column_stack([e[:, 1], -e[:, 0]])
    nrm /= np.hypot(nrm[:, 0], nrm[:, 1])[:, None]
    return np.ascontiguousarray(w), np.ascontiguousarray(nrm)


@st.composite
def pairs(draw):
    """Two placed polygons close enough to overlap about half the time."""
    scale = draw(st.sampled_from([0.01, 1.0, 100.0]))
    pa, pb = draw(polygons()), draw(polygons())
    d = draw(st.floats(0.0, 2.0))
    phi = draw(st.floats(0, 2 * math.pi))
    va, na = place(pa, 0.0, 0.0, draw(st.floats(0, 2 * math.pi)), scale)
    vb, nb = place(pb, scale * d * math.cos(phi), scale * d * math.sin(phi),
                   draw(st.floats(0, 2 * math.pi)), scale)
    return va, na, vb, nb, scale


def signed_distance(v, n, p):
    """Signed distance of point p to a convex polygon (exact outside, max-plane inside)."""
    planes = np.max(np.einsum("ij,ij->i", n, p - v))
    if planes <= 0.0:
        return planes
    best = math.inf
    for i in range(len(v)):
        a, b = v[i], v[(i + 1) % len(v)]
        e = b - a
        t = min(1.0, max(0.0, float(np.dot(p - a, e) / np.dot(e, e))))
        best = min(best, float(np.hypot(*(p - a - t * e))))
    return best


# -- SAT vs GJK vs EPA ---------------------------------------------------------
@settings(**SETTINGS)
@given(pairs())
def test_sat_and_gjk_agree_on_overlap(pair):
    va, na, vb, nb, scale = pair
    sep = sat_query(va, na, vb, nb)[0]
    dist = gjk_distance(va, vb)[0]
    tol = 1e-9 * scale
    if sep < -tol:
        assert dist == 0.0
    elif sep > tol:
        assert dist > 0.0
        # a separating axis bounds the distance from below
        assert dist >= sep - tol
    assert math.isfinite(dist)


@settings(**SETTINGS)
@given(pairs())
def test_gjk_distance_matches_witness_points(pair):
    va, na, vb, nb, scale = pair
    dist, nx, ny, pax, pay, pbx, pby = gjk_distance(va, vb)
    assume(dist > 1e-9 * scale)
    assert math.hypot(pbx - pax, pby - pay) == pytest.approx(dist, rel=1e-9)
    # witness points lie on the two boundaries
    assert abs(signed_distance(va, na, np.array([pax, pay]))) <= 1e-9 * scale
    assert abs(signed_distance(vb, nb, np.array([pbx, pby]))) <= 1e-9 * scale
    # and are the closest pair: the distance from each witness to the other shape
    assert signed_distance(vb, nb, np.array([pax, pay])) == pytest.approx(dist, rel=1e-7, abs=1e-12 * scale)


@settings(**SETTINGS)
@given(pairs())
def test_epa_depth_equals_sat_min_overlap(pair):
    va, na, vb, nb, scale = pair
    sep, snx, sny, _, _ = sat_query(va, na, vb, nb)
    assume(sep < -1e-6 * scale)
    depth, nx, ny = epa(va, vb)
    assert abs(depth + sep) <= 1e-6 * abs(sep) + 1e-12 * scale
    assert math.hypot(nx, ny) == pytest.approx(1.0, abs=1e-12)
    # EPA's normal is a face normal achieving that depth: translating B along it
    # by the depth is exactly the SAT separation along that axis
    moved = vb + depth * np.array([nx, ny])
    assert sat_query(va, na, moved, nb)[0] == pytest.approx(0.0, abs=1e-9 * scale)


@settings(**SETTINGS)
@given(pairs())
def test_moving_by_epa_vector_separates(pair):
    va, na, vb, nb, scale = pair
    depth, nx, ny = epa(va, vb)
    assume(depth > 1e-6 * scale)
    eps = 1e-6 * scale
    apart = vb + (depth + eps) * np.array([nx, ny])
    assert gjk_distance(va, apart)[0] > 0.0
    assert sat_query(va, na, apart, nb)[0] > 0.0
    # and the EPA vector is the shortest: a little less still overlaps
    still = vb + (depth - eps) * np.array([nx, ny])
    assert gjk_distance(va, still)[0] == 0.0


def test_identical_shapes_on_top_of_each_other_are_finite():
    for poly in (Polygon.box(1, 1), Polygon.regular(7, 1.0), Polygon.box(1.0, 1e-3)):
        va, na = place(poly, 3.0, -2.0, 0.3)
        depth, nx, ny = epa(va, va.copy())
        sep = sat_query(va, na, va.copy(), na.copy())[0]
        assert np.isfinite([depth, nx, ny]).all()
        assert depth == pytest.approx(-sep, rel=1e-9)
        for method in (SAT, GJK):
            c, mx, my, pts, seps, _ = polygon_collide(va, na, va.copy(), na.copy(), method, 0.0, 1e-3)
            assert c >= 1 and np.isfinite(pts[:c]).all() and np.isfinite([mx, my]).all()


def test_touching_shapes_give_zero_depth():
    va, na = place(Polygon.box(1, 1), 0.0, 0.0, 0.0)
    vb, nb = place(Polygon.box(1, 1), 0.3, 1.0, 0.0)     # exactly face to face
    depth, nx, ny = epa(va, vb)
    assert depth == pytest.approx(0.0, abs=1e-12) and (nx, ny) == pytest.approx((0.0, 1.0))
    vc, _ = place(Polygon.box(1, 1), 1.0, 1.0, 0.0)      # corner to corner
    assert np.isfinite(epa(va, vc)).all()


# -- manifolds -----------------------------------------------------------------
@settings(**SETTINGS)
@given(pairs(), st.sampled_from([SAT, GJK]))
def test_manifold_points_lie_on_both_shapes(pair, method):
    va, na, vb, nb, scale = pair
    margin = 0.05 * scale
    c, nx, ny, pts, seps, feats = polygon_collide(va, na, vb, nb, method, margin, 1e-3 * scale)
    sep = sat_query(va, na, vb, nb)[0]
    if sep > margin + 1e-9 * scale:
        assert c == 0
        return
    assume(c > 0)
    n = np.array([nx, ny])
    tol = 1e-8 * scale
    for p in range(c):
        depth = -seps[p]
        assert depth >= -margin - tol
        # the point is midway: half the depth back along n reaches A's surface,
        # half forward reaches B's (within A/B for overlap, on them when touching)
        on_a = pts[p] + 0.5 * depth * n
        on_b = pts[p] - 0.5 * depth * n
        if depth >= 0.0:
            assert signed_distance(va, na, on_a) <= tol
            assert signed_distance(vb, nb, on_b) <= tol
        else:
            # a speculative point: the feature it comes from is on its shape, and its gap is
            # measured along the face normal, so it may be less than that feature's true
            # distance to the other shape (near vertex-vertex: conservative, harmless) but never
            # more, or the solver would let the shapes close a gap it does not see
            da, db = signed_distance(va, na, on_a), signed_distance(vb, nb, on_b)
            assert min(da, db) <= tol
            # (measured from whichever end lies on its shape: the incident one sees the full gap)
            feature_gap = max(signed_distance(vb, nb, on_a) if da <= tol else -math.inf,
                              signed_distance(va, na, on_b) if db <= tol else -math.inf)
            assert -depth <= feature_gap + tol
        if depth > 0:  # no point is deeper than the penetration depth
            assert depth <= -sep + 1e-3 * scale + tol


@settings(**SETTINGS)
@given(pairs())
def test_sat_and_gjk_manifolds_are_equivalent(pair):
    va, na, vb, nb, scale = pair
    bias = 1e-3 * scale
    # every face of A and B (as an axis from A to B) with its separation
    seps = [(np.min((vb - va[i]) @ na[i]), na[i]) for i in range(len(va))]
    seps += [(np.min((va - vb[j]) @ nb[j]), -nb[j]) for j in range(len(vb))]
    top, top_n = max(seps, key=lambda t: t[0])
    assume(top < -1e-6 * scale)  # overlapping: EPA and SAT look for the same face of M
    # near-ties between different axes (e.g. concentric regular polygons) may
    # legitimately pick either; parallel faces of A and B are one face of M
    for s_, n_ in seps:
        assume(s_ < top - 2 * bias or float(n_ @ top_n) > 1 - 1e-9)
    r_sat = polygon_collide(va, na, vb, nb, SAT, 0.0, bias)
    r_gjk = polygon_collide(va, na, vb, nb, GJK, 0.0, bias)
    assert r_sat[0] == r_gjk[0]
    assert r_sat[1:3] == pytest.approx(r_gjk[1:3], abs=1e-9)
    c = r_sat[0]
    assert r_sat[4][:c] == pytest.approx(r_gjk[4][:c], abs=1e-9 * scale)
    assert (r_sat[5][:c] == r_gjk[5][:c]).all()


# -- circles -------------------------------------------------------------------
@settings(**SETTINGS)
@given(st.floats(0.01, 10), st.floats(0.01, 10), st.floats(0, 25), st.floats(0, 2 * math.pi),
       st.sampled_from([0.0, 1e4]))
def test_circle_circle_closed_form(ra, rb, d, phi, far):
    ax, ay = far, -far
    bx, by = ax + d * math.cos(phi), ay + d * math.sin(phi)
    out_p, out_s, out_f = np.zeros((2, 2)), np.zeros(2), np.zeros(2, np.int32)
    c, nx, ny = circle_circle(ax, ay, ra, bx, by, rb, 1.0, out_p, out_s, out_f)
    dist = math.hypot(bx - ax, by - ay)
    if dist - ra - rb > 1.0:
        assert c == 0
        return
    assert c == 1
    assert out_s[0] == pytest.approx(dist - ra - rb, abs=1e-9 * (1 + far))
    assert math.hypot(nx, ny) == pytest.approx(1.0)
    if dist > 1e-6:
        assert (nx, ny) == pytest.approx(((bx - ax) / dist, (by - ay) / dist), abs=1e-6)
    mid = np.array([ax, ay]) + (ra + 0.5 * out_s[0]) * np.array([nx, ny])
    assert out_p[0] == pytest.approx(mid, abs=1e-9 * (1 + far))


def test_coincident_circles_are_finite():
    out_p, out_s, out_f = np.zeros((2, 2)), np.zeros(2), np.zeros(2, np.int32)
    c, nx, ny = circle_circle(5.0, 5.0, 1.0, 5.0, 5.0, 0.5, 0.0, out_p, out_s, out_f)
    assert c == 1 and (nx, ny) == (0.0, 1.0) and out_s[0] == -1.5 and np.isfinite(out_p).all()


@settings(**SETTINGS)
@given(polygons(), st.floats(0, 2 * math.pi), st.floats(0.05, 1.5), st.floats(-2.5, 2.5),
       st.floats(-2.5, 2.5), st.sampled_from([0.01, 1.0, 100.0]))
def test_polygon_circle_closed_form(poly, angle, r, cx, cy, scale):
    v, n = place(poly, 0.0, 0.0, angle, scale)
    r, c = r * scale, np.array([cx, cy]) * scale
    out_p, out_s, out_f = np.zeros((2, 2)), np.zeros(2), np.zeros(2, np.int32)
    margin = 0.1 * scale
    cnt, nx, ny = polygon_circle(v, n, c[0], c[1], r, margin, out_p, out_s, out_f)
    sd = signed_distance(v, n, c)
    if sd - r > margin + 1e-9 * scale:
        assert cnt == 0
        return
    if sd - r < margin - 1e-9 * scale:
        assert cnt == 1
    if cnt == 0:
        return
    assert out_s[0] == pytest.approx(sd - r, abs=1e-9 * scale)
    nrm = np.array([nx, ny])
    assert np.linalg.norm(nrm) == pytest.approx(1.0)
    # midway point: the circle surface is half a separation ahead along n...
    assert np.linalg.norm(out_p[0] + 0.5 * out_s[0] * nrm - c) == pytest.approx(r, rel=1e-9)
    # ...and the polygon surface half a separation behind
    assert abs(signed_distance(v, n, out_p[0] - 0.5 * out_s[0] * nrm)) <= 1e-9 * scale
