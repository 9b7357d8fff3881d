"""The sandbox's compound-body helpers without a window (issue 13, "The sandbox"): body specs keep
every fixture, glue keeps each fixture where it is in the world, unglue gives each part its own
velocity, the sketch tool's RDP simplification, and the drawing of rounded outlines."""
from __future__ import annotations

import math

import numpy as np
import pytest

import physics
from app.fixture_specs import body_spec, glued_spec, make_body, unglued_specs
from app.render.parts import ARC, rounded_outlines
from app.tools.ground import ground_points
from app.tools.outline import area_centroid
from app.tools.sketch import rdp, simplified_outline


def world_points(body):
    """Every fixture's vertices in world coordinates, fixture by fixture."""
    c, s = math.cos(body.angle), math.sin(body.angle)
    rot = np.array([[c, -s], [s, c]])
    return [f.shape.vertices @ rot.T + body.position for f in body.fixtures]


def test_body_spec_keeps_every_fixture_material_and_filter():
    w = physics.World()
    b = w.add_body(physics.decompose([(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)]), position=(1, 2), angle=0.4)
    b.add_fixture(physics.Circle(0.3, offset=(2, 2)), density=3.0, friction=(0.9, 0.7), category=0x6, mask=0x3,
                  group=-2, name="knob")
    copy = make_body(w, dict(body_spec(b), name=None))
    assert len(copy.fixtures) == len(b.fixtures) == 3
    for f, g in zip(b.fixtures, copy.fixtures):
        assert (g.density, g.friction, g.category, g.mask, g.group, g.name) == \
            (f.density, f.friction, f.category, f.mask, f.group, f.name)
    assert copy.mass == pytest.approx(b.mass, rel=1e-12) and copy.inertia == pytest.approx(b.inertia, rel=1e-12)


def test_a_chain_travels_as_one_chain():
    w = physics.World()
    g = w.add_body(physics.Chain([(20, 0), (0, -1), (-20, 0)]), kind="static")
    spec = body_spec(g)
    assert len(spec["fixtures"]) == 1 and isinstance(spec["fixtures"][0]["shape"], physics.Chain)
    assert len(make_body(w, spec).fixtures) == 2


def test_glue_keeps_world_placement_mass_and_momentum():
    w = physics.World(gravity=(0, 0))
    a = w.add_body(physics.Polygon.box(1, 1), position=(-1, 0), angle=0.3, velocity=(2, 0))
    b = w.add_body(physics.Polygon.box(2, 1, radius=0.1), position=(2, 1), angle=-0.7, velocity=(0, 1), density=2.0)
    before = world_points(a) + world_points(b)
    p = a.mass * np.array(a.velocity) + b.mass * np.array(b.velocity)
    spec = glued_spec([a, b])
    m = a.mass + b.mass
    w.remove(a)
    w.remove(b)
    g = make_body(w, spec)
    for x, y in zip(before, world_points(g)):
        np.testing.assert_allclose(x, y, atol=1e-12)
    assert g.mass == pytest.approx(m, rel=1e-12)
    np.testing.assert_allclose(g.mass * np.array(g.velocity), p, rtol=1e-12)
    assert g.fixtures[1].density == 2.0 and g.fixtures[1].shape.radius == pytest.approx(0.1)


def test_unglue_gives_each_part_the_velocity_of_where_it_is():
    w = physics.World(gravity=(0, 0))
    g = w.add_body([physics.Polygon.box(1, 1), physics.Circle(0.5, offset=(3, 0))], position=(1, 1), angle=0.5,
                   velocity=(1, -1), angular_velocity=2.0)
    com = np.array(g.center_of_mass)
    for spec in unglued_specs(g):
        part = make_body(w, spec)
        r = np.array(part.center_of_mass) - com           # rigid motion: v + w x r
        np.testing.assert_allclose(part.velocity, np.array([1, -1]) + 2.0 * np.array([-r[1], r[0]]), atol=1e-12)


def test_rdp_drops_points_within_tolerance_and_keeps_corners():
    t = np.linspace(0, 1, 50)
    side = np.stack([t * 4, 0.001 * np.sin(40 * t)], 1)        # a wobbly 4 m edge
    pts = np.concatenate([side, [[4, 3]], [[0, 3]]])
    out = rdp(pts, 0.01)
    np.testing.assert_allclose(out[[0, -3, -2, -1]], [[0, 0], side[-1], [4, 3], [0, 3]], atol=1e-12)
    assert len(out) == 4
    assert len(rdp(pts, 1e-6)) > 10                               # a tolerance below the wobble keeps it
    closed = simplified_outline(np.concatenate([pts, [[0.01, 0.0]]]), scale=40.0)
    assert len(closed) == 4                                       # the closing point goes


def test_rounded_outline_is_the_minkowski_sum():
    """Every outline point lies at the radius from the core polygon, and the arcs' area tends to
    the rounded box's area w h + 2 r (w + h) + pi r^2."""
    w_, h_, r = 2.0, 1.0, 0.3
    core = physics.Polygon.box(w_, h_).vertices
    pts, start, count = rounded_outlines(core, np.array([0]), np.array([4]), np.array([r]))
    assert count[0] == 4 * ARC
    d = np.min(np.hypot(*(pts[:, None, :] - core[None]).transpose(2, 0, 1)), axis=1)
    np.testing.assert_allclose(d, r, rtol=1e-12)
    exact = w_ * h_ + 2 * r * (w_ + h_) + math.pi * r * r
    x, y = pts.T
    area = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
    # ARC points a quarter circle: the inscribed polygon's deficit is r^2 (pi - n sin(pi/n) ... ) < 1 %
    assert 0.99 * exact < area < exact


def test_capsule_outline_is_a_stadium():
    pts, _, count = rounded_outlines(np.array([[-1.0, 0.0], [1.0, 0.0]]), np.array([0]), np.array([2]),
                                     np.array([0.5]))
    assert count[0] == 2 * ARC
    # each end a half circle of ARC points: the tip lies within the chord sagitta r (1 - cos(h/2))
    # of the true 1.5 m, h = pi / (ARC - 1) the angle between arc points
    sag = 0.5 * (1 - math.cos(0.5 * math.pi / (ARC - 1)))
    assert 1.5 - sag - 1e-12 <= pts[:, 0].max() <= 1.5 and -1.5 <= pts[:, 0].min() <= -1.5 + sag + 1e-12
    assert pts[:, 1].max() == pytest.approx(0.5) and pts[:, 1].min() == pytest.approx(-0.5)
    ends = np.clip(pts[:, 0], -1, 1)                       # distance to the core segment: the radius
    np.testing.assert_allclose(np.hypot(pts[:, 0] - ends, pts[:, 1]), 0.5, rtol=1e-12)


def test_ground_points_run_right_to_left_and_area_centroid():
    assert ground_points([(0, 0), (5, 1)])[0, 0] == 5
    assert ground_points([(5, 0), (0, 1)])[0, 0] == 5
    l_shape = np.array([(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)], float)
    # two rectangles: 3x1 centred (1.5, 0.5) and 1x2 centred (0.5, 2)
    np.testing.assert_allclose(area_centroid(l_shape), [(3 * 1.5 + 2 * 0.5) / 5, (3 * 0.5 + 2 * 2) / 5])
    np.testing.assert_allclose(area_centroid(l_shape[::-1]), area_centroid(l_shape))
