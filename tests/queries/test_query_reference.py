"""Every query agrees with the brute-force reference (tests/queries/reference.py) on random
worlds of every fixture shape: polygons, rounded polygons, circles, capsules, segments, chains.

Fractions agree to 1e-7 (the reference bisects to ~1e-15; 1e-7 covers the conditioning of a
shallow entry).  Grazing contacts, where the reference's minimum of h is within 1e-7 of zero,
are a matter of rounding and are left out of both sides; the tests count that they compare
real hits (a test that compared nothing would pass).
"""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import physics
from tests.queries.reference import cast_fraction, point_distance, ray_fraction, separation, world_core
from tests.queries.worlds import all_fixtures, coord, worlds

# one worker, in file order: the last test counts the hits the others compared (pytest-xdist)
pytestmark = pytest.mark.xdist_group("query_reference")
CFG = settings(max_examples=40, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
TOL = 1e-7
points = st.tuples(coord, coord)
HITS = {"ray": 0, "box": 0, "cast": 0}


def _seen(fx, category=1, mask=0xFFFF):
    return bool(fx.category & mask) and bool(fx.mask & category)


def _reference_hits(w, p, e):
    hits, vague = {}, set()
    for fx in all_fixtures(w):
        if not _seen(fx):
            continue
        t, amb = ray_fraction(fx, p, e)
        if amb < TOL:
            vague.add(fx.id)
        elif t is not None:
            hits[fx.id] = t
    return hits, vague


@CFG
@given(worlds(), points, points)
def test_ray_cast_all_hits_match(w, p, e):
    want, vague = _reference_hits(w, p, e)
    got = w.ray_cast(p, e)
    fr = [h.fraction for h in got]
    assert fr == sorted(fr)
    have = {h.fixture.id: h for h in got if h.fixture.id not in vague}
    assert set(have) == set(want)
    for fid, h in have.items():
        assert abs(h.fraction - want[fid]) < TOL
        assert np.allclose(h.point, np.array(p) + h.fraction * (np.array(e) - p))
        if h.fraction > 0:  # the normal is a unit vector facing the ray's start
            n = np.array(h.normal)
            assert abs(np.hypot(*n) - 1) < 1e-9 and n @ (np.array(e) - p) <= 1e-12
        else:
            assert h.normal == (0.0, 0.0)
    HITS["ray"] += len(have)


@CFG
@given(worlds(), st.lists(st.tuples(points, points), min_size=1, max_size=8))
def test_first_and_many_agree_with_all(w, rays):
    S = np.array([r[0] for r in rays])
    E = np.array([r[1] for r in rays])
    many = w.ray_cast_many(S, E)
    for i, (p, e) in enumerate(rays):
        every = w.ray_cast(p, e)
        first = w.ray_cast(p, e, first=True)
        assert len(first) == (1 if every else 0)
        if every:
            assert first[0].fraction == every[0].fraction
            assert many["fraction"][i] == first[0].fraction
            assert many["fixture"][i] == first[0].fixture.id and many["body"][i] == first[0].body.id
            assert tuple(many["normal"][i]) == first[0].normal
        else:
            assert many["fixture"][i] == -1 and many["fraction"][i] == -1


@CFG
@given(worlds(), points, st.tuples(st.floats(0, 6), st.floats(0, 6)))
def test_query_aabb_is_exact(w, lo, extent):
    hi = (lo[0] + extent[0], lo[1] + extent[1])
    box = np.array([lo, (hi[0], lo[1]), hi, (lo[0], hi[1])])
    got = {f.id for f in w.query_aabb(lo, hi)}
    for fx in all_fixtures(w):
        P, r = world_core(fx)
        gap = separation(box, P) - r
        if abs(gap) < TOL or not _seen(fx):
            continue
        assert (fx.id in got) == (gap <= 0), (fx, gap)
        HITS["box"] += gap <= 0


@CFG
@given(worlds(), points)
def test_query_point_all_is_exact(w, p):
    got = {f.id for f in w.query_point_all(p)}
    for fx in all_fixtures(w):
        P, r = world_core(fx)
        gap = point_distance(p, P) - r
        if abs(gap) < TOL or not _seen(fx):
            continue
        assert (fx.id in got) == (gap <= 0)
    top = w.query_point(p)
    if got and top is not None:  # the topmost body is one of those found
        assert top.id in {f.body.id for f in w.query_point_all(p)}


def _query_shapes():
    return st.sampled_from([physics.Circle(0.7), physics.Circle(0.4, offset=(0.3, -0.2)),
                            physics.Polygon.box(1.5, 0.6), physics.Polygon.box(1.0, 1.0, radius=0.2),
                            physics.Polygon.regular(5, 0.8), physics.Capsule((-0.5, 0), (0.5, 0), 0.3),
                            physics.Segment((-1, 0), (1, 0.5))])


@CFG
@given(worlds(), _query_shapes(), points, st.floats(-3.2, 3.2))
def test_overlap_is_exact(w, shape, pos, angle):
    from physics.queries.placed import placed_core
    P, rp = placed_core(shape, pos, angle)
    got = {f.id for f in w.overlap(shape, pos, angle)}
    for fx in all_fixtures(w):
        Q, rq = world_core(fx)
        gap = separation(P, Q) - rp - rq
        if abs(gap) < TOL or not _seen(fx):
            continue
        assert (fx.id in got) == (gap <= 0)


@CFG
@given(worlds(), _query_shapes(), points, st.floats(-3.2, 3.2), st.tuples(st.floats(-12, 12), st.floats(-12, 12)))
def test_shape_cast_finds_the_first_contact(w, shape, pos, angle, move):
    from physics.queries.placed import placed_core
    P, rp = placed_core(shape, pos, angle)
    best, vague = None, False
    for fx in all_fixtures(w):
        if not _seen(fx):
            continue
        t, amb = cast_fraction(P, rp, move, fx)
        vague |= amb < TOL
        if t is not None and (best is None or t < best[0]):
            best = (t, fx.id)
    if vague:
        return
    hit = w.shape_cast(shape, pos, angle, move)
    if best is None:
        assert hit is None
        return
    assert hit is not None and abs(hit.fraction - best[0]) < 1e-6
    HITS["cast"] += 1
    if hit.fraction > 0:
        Q, rq = world_core(hit.fixture)
        # the contact point is on the fixture's surface and the normal is a unit vector
        assert abs(point_distance(hit.point, Q) - rq) < 1e-6
        assert abs(np.hypot(*hit.normal) - 1) < 1e-9


def test_the_property_tests_compared_real_hits():
    """Run after the others (file order): each kind of query met real hits, not just misses."""
    assert HITS["ray"] > 10 and HITS["box"] > 5 and HITS["cast"] > 5, HITS  # a run here: 26, 10, 24
