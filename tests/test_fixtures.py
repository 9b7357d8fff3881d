"""Bodies made of several fixtures (issue 13): the API, mass properties against closed forms,
the collision filter's truth table, and no collision between the fixtures of one body.

Closed forms: a rectangle's polar moment m (w^2 + h^2) / 12 and the parallel-axis theorem
(Goldstein, Classical Mechanics, sec. 5.3); a disc's m r^2 / 2; a half disc's centroid 4r/(3 pi)
from its flat edge.  Tolerances are round-off (1e-12 relative) since every number is exact.
"""
import math

import numpy as np
import pytest

import physics
from physics.store.fixtures import ALL_BITS

from builders import world


def rect_inertia(m, w, h):
    return m * (w * w + h * h) / 12.0


def test_add_body_takes_a_list_and_reports_its_fixtures():
    w = world()
    car = w.add_body([physics.Polygon.box(4, 0.5), physics.Circle(0.3, offset=(1.5, -0.4))], position=(0, 3),
                     density=2.0, friction=(0.9, 0.7), restitution=0.2)
    assert len(car.fixtures) == 2
    assert all(f.body is car and f.density == 2.0 and f.friction == (0.9, 0.7) and f.restitution == 0.2
               for f in car.fixtures)
    assert [type(f.shape) for f in car.fixtures] == [physics.Polygon, physics.Circle]
    assert car.shape is car.fixtures[0].shape
    m_box, m_disc = 2.0 * 4 * 0.5, 2.0 * math.pi * 0.09
    assert car.mass == pytest.approx(m_box + m_disc, rel=1e-12)
    cx = m_disc * 1.5 / (m_box + m_disc)
    cy = m_disc * -0.4 / (m_box + m_disc)
    assert car.center_of_mass == pytest.approx((cx, 3 + cy), rel=1e-12)
    i = rect_inertia(m_box, 4, 0.5) + m_box * (cx * cx + cy * cy) \
        + 0.5 * m_disc * 0.09 + m_disc * ((1.5 - cx) ** 2 + (-0.4 - cy) ** 2)
    assert car.inertia == pytest.approx(i, rel=1e-12)
    assert car.position == pytest.approx((0, 3), abs=1e-12)


def test_add_and_remove_fixture_move_the_mass_and_keep_the_origin():
    w = world()
    b = w.add_body(physics.Polygon.box(1, 1), position=(2, 3), angle=0.3)
    m0, i0 = b.mass, b.inertia
    f = b.add_fixture(physics.Capsule((0, 0), (1, 0), 0.1), density=2.0, friction=(0.9, 0.7), restitution=0.2,
                      category=0x2, mask=0x1, group=0, name="arm")
    assert (f.density, f.friction, f.restitution, f.category, f.mask, f.group, f.name) == \
        (2.0, (0.9, 0.7), 0.2, 2, 1, 0, "arm")
    assert b.mass == pytest.approx(m0 + 2.0 * (0.2 + math.pi * 0.01), rel=1e-12)
    assert b.position == pytest.approx((2, 3), abs=1e-12)
    f.density = 4.0  # mass follows density
    assert b.mass == pytest.approx(m0 + 4.0 * (0.2 + math.pi * 0.01), rel=1e-12)
    b.remove_fixture(f)
    assert not f.alive and len(b.fixtures) == 1
    assert (b.mass, b.inertia) == pytest.approx((m0, i0), rel=1e-12)
    assert b.position == pytest.approx((2, 3), abs=1e-12)
    with pytest.raises(ValueError, match="at least one fixture"):
        b.remove_fixture(b.fixtures[0])


@pytest.mark.parametrize("field, value, words", [
    ("density", -1, "density"), ("density", "1", "density"), ("friction", -0.1, "friction"),
    ("restitution", 1.5, "restitution"), ("category", -1, "category"), ("category", 2 ** 64, "category"),
    ("mask", 1.5, "mask"), ("group", 2 ** 31, "group"), ("group", True, "group"), ("name", 3, "name"),
])
def test_fixture_setters_validate_and_name_the_field(field, value, words):
    w = world()
    f = w.add_body(physics.Polygon.box(1, 1)).fixtures[0]
    before = getattr(f, field)
    with pytest.raises(ValueError, match=words):
        setattr(f, field, value)
    assert getattr(f, field) == before


def test_body_material_sets_every_fixture_and_reads_the_first():
    w = world()
    b = w.add_body([physics.Polygon.box(1, 1), physics.Circle(0.5, offset=(1, 0))])
    b.friction = (0.3, 0.2)
    b.restitution = 0.4
    b.fixtures[1].friction = 0.9
    assert b.friction == (0.3, 0.2) and [f.restitution for f in b.fixtures] == [0.4, 0.4]
    assert b.fixtures[1].friction == (0.9, 0.9)


def test_segments_need_a_static_or_kinematic_body():
    w = world()
    with pytest.raises(ValueError, match="dynamic body needs a shape with area"):
        w.add_body(physics.Segment((0, 0), (1, 0)))
    with pytest.raises(ValueError, match="dynamic body needs a shape with area"):
        w.add_body(physics.Chain([(1, 0), (0, 0)]))
    s = w.add_body(physics.Segment((0, 0), (1, 0)), kind="static")
    with pytest.raises(ValueError, match="area"):
        s.kind = "dynamic"
    assert s.kind == "static"
    assert w.bodies == [s]


# -- mass properties against closed forms, both windings ---------------------------------
@pytest.mark.parametrize("wind", [1, -1])
def test_l_shape_from_decompose(wind):
    outline = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)][::wind]
    w = world()
    b = w.add_body(physics.decompose(outline), density=2.0)
    # the L = a 3 x 1 bar (centre (1.5, 0.5)) + a 1 x 2 post (centre (0.5, 2))
    m1, m2 = 2.0 * 3, 2.0 * 2
    c = (np.array([1.5, 0.5]) * m1 + np.array([0.5, 2.0]) * m2) / (m1 + m2)
    i = rect_inertia(m1, 3, 1) + m1 * np.sum((c - (1.5, 0.5)) ** 2) \
        + rect_inertia(m2, 1, 2) + m2 * np.sum((c - (0.5, 2.0)) ** 2)
    assert b.mass == pytest.approx(m1 + m2, rel=1e-12)
    assert b.center_of_mass == pytest.approx(tuple(c), rel=1e-12)
    assert b.inertia == pytest.approx(i, rel=1e-12)


def test_ring_of_boxes():
    # n boxes w x h, centres on a circle of radius R: I = n (m (w^2 + h^2)/12 + m R^2), centre at 0
    n, R, bw, bh = 12, 3.0, 0.5, 0.2
    shapes = []
    for k in range(n):
        a = 2 * math.pi * k / n
        c, s = math.cos(a), math.sin(a)
        corners = [(R + x, y) for x, y in ((-bh / 2, -bw / 2), (bh / 2, -bw / 2), (bh / 2, bw / 2), (-bh / 2, bw / 2))]
        shapes.append(physics.Polygon([(c * x - s * y, s * x + c * y) for x, y in corners]))
    w = world()
    b = w.add_body(shapes, kind="kinematic")
    m = bw * bh
    assert b.center_of_mass == pytest.approx((0, 0), abs=1e-12)
    assert b.mass == pytest.approx(n * m, rel=1e-12)
    assert b.inertia == pytest.approx(n * (rect_inertia(m, bw, bh) + m * R * R), rel=1e-12)


@pytest.mark.parametrize("wind", [1, -1])
def test_capsule_is_a_rectangle_and_two_half_discs(wind):
    a, b_ = ((0.0, 0.0), (2.0, 0.0))[::wind]
    L, r = 2.0, 0.5
    cap = physics.Capsule(a, b_, r)
    m, c, i = cap.mass_properties(3.0)
    rect = 3.0 * 2 * r * L
    half = 3.0 * math.pi * r * r / 2
    d = 4 * r / (3 * math.pi)                  # half disc centroid from its flat edge
    i_half = half * r * r / 2 - half * d * d   # about its own centroid
    expect = rect_inertia(rect, L, 2 * r) + 2 * (i_half + half * (L / 2 + d) ** 2)
    assert m == pytest.approx(rect + 2 * half, rel=1e-12)
    assert c == pytest.approx((1.0, 0.0), abs=1e-12)
    assert i == pytest.approx(expect, rel=1e-12)


@pytest.mark.parametrize("wind", [1, -1])
def test_rounded_box(wind):
    # a w x h box rounded by r: the core, four edge strips and four quarter discs at the corners
    bw, bh, r = 2.0, 1.0, 0.25
    pts = [(-1, -0.5), (1, -0.5), (1, 0.5), (-1, 0.5)][::wind]
    poly = physics.Polygon(pts, radius=r)
    m, c, i = poly.mass_properties(1.0)
    parts = [(bw * bh, 0, 0, rect_inertia(bw * bh, bw, bh))]
    for cx, cy, sw, sh in ((0, bh / 2 + r / 2, bw, r), (0, -bh / 2 - r / 2, bw, r),
                           (bw / 2 + r / 2, 0, r, bh), (-bw / 2 - r / 2, 0, r, bh)):
        parts.append((sw * sh, cx, cy, rect_inertia(sw * sh, sw, sh)))
    q = math.pi * r * r / 4
    d = 4 * r / (3 * math.pi)
    for sx in (1, -1):
        for sy in (1, -1):
            px, py = sx * (bw / 2 + d), sy * (bh / 2 + d)
            parts.append((q, px, py, q * r * r / 2 - q * 2 * d * d))
    area = sum(p[0] for p in parts)
    expect = sum(p[3] + p[0] * (p[1] ** 2 + p[2] ** 2) for p in parts)
    assert m == pytest.approx(area, rel=1e-12) and poly.area == pytest.approx(area, rel=1e-12)
    assert c == pytest.approx((0, 0), abs=1e-12)
    assert i == pytest.approx(expect, rel=1e-12)


# -- collision filtering -----------------------------------------------------------------
FILTER_CASES = [  # (category_a, mask_a, group_a, category_b, mask_b, group_b, collide)
    (1, ALL_BITS, 0, 1, ALL_BITS, 0, True),
    (0x2, 0x1, 0, 0x1, 0x2, 0, True),
    (0x2, 0x1, 0, 0x1, 0x1, 0, False),      # b does not accept a's category
    (0x2, 0x4, 0, 0x1, 0x2, 0, False),      # a does not accept b's category
    (0x1, 0x0, 3, 0x1, 0x0, 3, True),       # a shared positive group overrides the masks
    (0x1, ALL_BITS, -3, 0x1, ALL_BITS, -3, False),  # a shared negative group never collides
    (0x1, ALL_BITS, -3, 0x1, ALL_BITS, -4, True),   # different groups: the bits decide
    (0x1, 0x0, 3, 0x1, ALL_BITS, 4, False),
    (1 << 63, 1 << 63, 0, 1 << 63, 1 << 63, 0, True),  # the top bit works
]


@pytest.mark.parametrize("ca, ma, ga, cb, mb, gb, collide", FILTER_CASES)
def test_filter_truth_table(ca, ma, ga, cb, mb, gb, collide):
    w = world()
    g = w.add_body(physics.Polygon.box(10, 1), kind="static", position=(0, -0.5))
    b = w.add_body(physics.Polygon.box(1, 1), position=(0, 0.45))
    g.fixtures[0].category, g.fixtures[0].mask, g.fixtures[0].group = ca, ma, ga
    b.fixtures[0].category, b.fixtures[0].mask, b.fixtures[0].group = cb, mb, gb
    w.step()
    assert bool(w.contacts()) == collide
    for _ in range(30):
        w.step()
    assert (b.position[1] > 0.3) == collide   # held up, or fallen through


def test_fixtures_of_one_body_never_collide_and_contacts_name_fixtures():
    w = world()
    w.add_body(physics.Polygon.box(10, 1), kind="static", position=(0, -0.5), name="ground")
    # two overlapping boxes of one body: no contact between them, no push apart
    b = w.add_body([physics.Polygon.box(1, 1), physics.Polygon([(0, -0.5), (1, -0.5), (1, 0.5), (0, 0.5)])],
                   position=(0, 0.5))
    for _ in range(60):
        w.step()
    cs = w.contacts()
    assert cs and all({c.body_a, c.body_b} == {w.body("ground"), b} for c in cs)
    assert {c.fixture_b if c.body_b is b else c.fixture_a for c in cs} <= set(b.fixtures)
    assert abs(b.angular_velocity) < 1e-3 and abs(b.velocity[1]) < 1e-2
