"""Shapes: mass properties against closed forms, winding, hulls, validation.

Closed forms (polar second moment about the centroid):
- rectangle w x h: I = m (w^2 + h^2) / 12
- regular n-gon, circumradius R: A = n R^2 sin(2 pi / n) / 2,
  I = m R^2 (1 + 2 cos^2(pi / n)) / 6  (n = 4 gives the square's m s^2 / 6;
  n -> infinity the disc's m R^2 / 2)
- triangle with sides a, b, c: I = m (a^2 + b^2 + c^2) / 36
  (a right triangle with legs a, b: m (a^2 + b^2) / 18)
- disc: I = m r^2 / 2
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physics.geometry.shapes import Circle, Polygon

rel = dict(rel=1e-12, abs=1e-12)


def triangle_inertia(p, m):
    a2, b2, c2 = (float(np.sum((p[i] - p[(i + 1) % 3]) ** 2)) for i in range(3))
    return m * (a2 + b2 + c2) / 36.0


@given(st.floats(0.01, 100), st.floats(0.01, 100), st.floats(0.1, 10))
def test_box(w, h, rho):
    m, c, inertia = Polygon.box(w, h).mass_properties(rho)
    assert m == pytest.approx(rho * w * h, rel=1e-12)
    np.testing.assert_allclose(c, 0.0, atol=1e-12 * max(w, h))
    assert inertia == pytest.approx(m * (w * w + h * h) / 12.0, rel=1e-11)


@pytest.mark.parametrize("sides", [3, 4, 5, 6, 8, 13, 64])
@pytest.mark.parametrize("radius", [0.05, 1.0, 7.5])
def test_regular_polygon(sides, radius):
    rho = 3.0
    m, c, inertia = Polygon.regular(sides, radius).mass_properties(rho)
    area = sides * radius ** 2 * math.sin(2 * math.pi / sides) / 2
    assert m == pytest.approx(rho * area, rel=1e-12)
    np.testing.assert_allclose(c, 0.0, atol=1e-12 * radius)
    want = m * radius ** 2 * (1 + 2 * math.cos(math.pi / sides) ** 2) / 6
    assert inertia == pytest.approx(want, rel=1e-11)


def test_regular_polygon_formula_limits():
    # the closed form itself: square with side s, and the disc limit
    s = 2.0
    m, _, inertia = Polygon.regular(4, s / math.sqrt(2)).mass_properties(1.0)
    assert inertia == pytest.approx(m * s * s / 6, rel=1e-12)
    m, _, inertia = Polygon.regular(64, 1.0).mass_properties(1.0)
    assert inertia == pytest.approx(m / 2, rel=2e-3)


@given(st.floats(0.1, 10), st.floats(0.1, 10))
def test_right_triangle(a, b):
    m, c, inertia = Polygon([(0, 0), (a, 0), (0, b)]).mass_properties(1.0)
    assert m == pytest.approx(a * b / 2, rel=1e-12)
    np.testing.assert_allclose(c, (a / 3, b / 3), rtol=1e-12)
    assert inertia == pytest.approx(m * (a * a + b * b) / 18, rel=1e-11)


@settings(max_examples=200)
@given(st.lists(st.tuples(st.floats(-10, 10), st.floats(-10, 10)), min_size=3, max_size=3))
def test_general_triangle(pts):
    p = np.array(pts)
    area = 0.5 * abs((p[1, 0] - p[0, 0]) * (p[2, 1] - p[0, 1]) - (p[2, 0] - p[0, 0]) * (p[1, 1] - p[0, 1]))
    sides = sorted(np.hypot(*(p - np.roll(p, 1, 0)).T))
    if area < 1e-3 * max(sides[-1], 1e-3) ** 2:
        return  # slivers are rejected or ill-conditioned; validated elsewhere
    m, c, inertia = Polygon(p).mass_properties(2.0)
    assert m == pytest.approx(2.0 * area, rel=1e-9)
    np.testing.assert_allclose(c, p.mean(axis=0), atol=1e-9 * sides[-1])
    assert inertia == pytest.approx(triangle_inertia(p, m), rel=1e-9)


def test_circle():
    m, c, inertia = Circle(0.5, offset=(2.0, -1.0)).mass_properties(4.0)
    assert m == pytest.approx(4.0 * math.pi * 0.25, rel=1e-15)
    np.testing.assert_array_equal(c, (2.0, -1.0))
    assert inertia == pytest.approx(m * 0.25 / 2, rel=1e-15)


@settings(max_examples=100)
@given(st.lists(st.tuples(st.floats(-5, 5), st.floats(-5, 5)), min_size=3, max_size=40))
def test_both_windings_agree(pts):
    try:
        ccw = Polygon.hull(pts)
    except ValueError:
        return  # fewer than three non-collinear points
    cw = Polygon(ccw.vertices[::-1])
    assert cw.vertices.shape == ccw.vertices.shape
    a, b = ccw.mass_properties(1.7), cw.mass_properties(1.7)
    assert a[0] == pytest.approx(b[0], rel=1e-12)
    np.testing.assert_allclose(a[1], b[1], atol=1e-12 * 5)
    assert a[2] == pytest.approx(b[2], rel=1e-10)
    assert _is_ccw(cw.vertices)


def _is_ccw(v):
    e = np.roll(v, -1, 0) - v
    cross = e[:, 0] * np.roll(e, -1, 0)[:, 1] - e[:, 1] * np.roll(e, -1, 0)[:, 0]
    return bool(np.all(cross > 0))


@pytest.mark.parametrize("offset", [(3.0, -2.0), (1e4, 1e4), (-1e5, 3e5), (1e6, -1e6)])
def test_offset_polygon_moves_only_the_centroid(offset):
    base = Polygon.regular(7, 1.3)
    m0, c0, i0 = base.mass_properties(2.0)
    moved = Polygon(base.vertices + np.array(offset))
    m, c, inertia = moved.mass_properties(2.0)
    scale = max(abs(x) for x in offset)
    assert m == pytest.approx(m0, rel=1e-15 * scale * 10 + 1e-12)
    np.testing.assert_allclose(c, c0 + offset, rtol=0, atol=1e-15 * scale * 10)
    assert inertia == pytest.approx(i0, rel=1e-15 * scale * 10 + 1e-12)
    assert moved.area == pytest.approx(base.area, rel=1e-15 * scale * 10 + 1e-12)


def test_offset_box_parallel_axis():
    w, h = 2.0, 0.5
    m, c, inertia = Polygon([(10, 20), (10 + w, 20), (10 + w, 20 + h), (10, 20 + h)]).mass_properties(1.0)
    np.testing.assert_allclose(c, (11.0, 20.25), rtol=1e-15)
    assert inertia == pytest.approx(m * (w * w + h * h) / 12, rel=1e-12)


@settings(max_examples=200)
@given(st.lists(st.tuples(st.floats(-100, 100), st.floats(-100, 100)), min_size=3, max_size=60))
def test_hull_contains_points_and_is_convex(pts):
    p = np.array(pts)
    try:
        hull = Polygon.hull(p)
    except ValueError as exc:
        assert any(w in str(exc) for w in ("no area", "zero area", "at most")), exc
        return
    v = hull.vertices
    assert _is_ccw(v)
    # every point on the inner side of every edge (up to rounding)
    e = np.roll(v, -1, 0) - v
    d = (p[:, None, 0] - v[None, :, 0]) * e[None, :, 1] - (p[:, None, 1] - v[None, :, 1]) * e[None, :, 0]
    assert np.all(d <= 1e-8 * (1 + np.abs(p).max()) * np.hypot(e[:, 0], e[:, 1]).max())
    # hull vertices are input points
    assert all(any(np.array_equal(x, y) for y in p) for x in v)


@pytest.mark.parametrize("verts, words", [
    ([(0, 0), (2, 0), (1, 0.5), (2, 2), (0, 2)], "not convex"),
    ([(math.cos(math.pi / 2 + 4 * math.pi * k / 5), math.sin(math.pi / 2 + 4 * math.pi * k / 5))
      for k in range(5)], "self-intersecting"),
    ([(0, 0), (1, 0), (2, 0), (1, 1)], "collinear"),
    ([(0, 0), (1, 0), (2, 0)], "zero area"),
    ([(0, 0), (1, 1), (2, 2), (3, 3)], "zero area"),
    ([(1, 1), (1, 1), (1, 1)], "zero area"),
    ([(0, 0), (1, 0), (1, 0), (0, 1)], "repeated"),
    ([(0, 0), (1, 0), (1, 1), (0, 1), (0, 0)], "repeated"),
    ([(0, 0), (1, float("nan")), (0, 1)], "finite"),
    ([(0, 0), (1, float("inf")), (0, 1)], "finite"),
    ([(0, 0), (1, 0)], "at least 3"),
    ([], "pairs"),
    ([(0, 0, 0), (1, 0, 0), (0, 1, 0)], "(x, y) pairs"),
    ([[(0, 0)], 1], "(x, y) pairs"),
])
def test_bad_polygons_name_the_problem(verts, words):
    with pytest.raises(ValueError, match=words.replace("(", r"\(").replace(")", r"\)")):
        Polygon(verts)


def test_too_many_vertices():
    with pytest.raises(ValueError, match="sides"):
        Polygon.regular(65, 1.0)
    ring = [(math.cos(t), math.sin(t)) for t in np.linspace(0, 2 * math.pi, 100, endpoint=False)]
    with pytest.raises(ValueError, match="at most"):
        Polygon(ring)


@pytest.mark.parametrize("w, h", [(0, 1), (1, 0), (-1, 1), (1, -2), (float("nan"), 1), (1, float("inf"))])
def test_bad_box(w, h):
    with pytest.raises(ValueError, match="box size"):
        Polygon.box(w, h)


@pytest.mark.parametrize("r", [0, -1, float("nan"), float("inf")])
def test_bad_circle_and_regular(r):
    with pytest.raises(ValueError, match="radius"):
        Circle(r)
    with pytest.raises(ValueError, match="radius"):
        Polygon.regular(5, r)
    with pytest.raises(ValueError, match="sides"):
        Polygon.regular(2, 1.0)
    with pytest.raises(ValueError, match="sides"):
        Polygon.regular(4.5, 1.0)


def test_hull_drops_nearly_collinear_and_nearly_repeated_points():
    # found by hypothesis: exact-arithmetic hulls kept these, then Polygon() rejected them
    assert len(Polygon.hull([(0, 0), (0, 1), (1, -1e-94), (2, 0)]).vertices) == 3
    assert len(Polygon.hull([(0, 0), (0, 1), (1, 0), (1, 1e-94)]).vertices) == 3


def test_hull_of_degenerate_points():
    with pytest.raises(ValueError, match="no area"):
        Polygon.hull([(0, 0), (1, 1), (2, 2), (1, 1)])
    with pytest.raises(ValueError, match="finite"):
        Polygon.hull([(0, 0), (1, 0), (float("nan"), 1)])
