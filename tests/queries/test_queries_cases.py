"""Hand-checked query cases: analytic fractions, starts inside, one-sided chains, filters,
cache refresh after edits and steps, refusals."""
from __future__ import annotations

import math

import numpy as np
import pytest

import physics


def _world():
    w = physics.World(gravity=(0, 0))
    ground = w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    ball = w.add_body(physics.Circle(1.0), position=(0, 3))
    cap = w.add_body(physics.Capsule((-1, 0), (1, 0), 0.5), position=(5, 2))
    return w, ground, ball, cap


def test_vertical_ray_hits_in_order_with_analytic_fractions():
    w, ground, ball, _ = _world()
    hits = w.ray_cast((0, 10), (0, -10))
    assert [h.body for h in hits] == [ball, ground]
    # top of the ball at y = 4: (10 - 4) / 20; ground top at y = 0: 10 / 20
    assert hits[0].fraction == pytest.approx(0.3, abs=1e-15) and hits[0].normal == (0.0, 1.0)
    assert hits[1].fraction == 0.5 and hits[1].point == (0.0, 0.0)
    assert w.ray_cast((0, 10), (0, -10), first=True) == hits[:1]


def test_slanted_ray_into_a_capsule_cap():
    w, _, _, cap = _world()
    # aim at the right cap's centre (6, 2) from (10, 2 + 4 tan 30deg): enters at distance 4/cos - 0.5
    p = np.array([10.0, 2 + 4 * math.tan(math.radians(30))])
    e = np.array([6.0, 2.0])
    [hit] = w.ray_cast(p, e)
    L = np.hypot(*(e - p))
    assert hit.body is cap and hit.fraction == pytest.approx((L - 0.5) / L, rel=1e-12)
    assert np.allclose(hit.normal, (p - e) / L, atol=1e-12)


def test_a_ray_starting_inside_hits_at_zero():
    w, _, ball, _ = _world()
    [hit, _] = w.ray_cast((0, 3.5), (0, -10))
    assert hit.body is ball and hit.fraction == 0.0 and hit.normal == (0.0, 0.0) and hit.point == (0.0, 3.5)


def test_chain_segments_are_one_sided():
    w = physics.World(gravity=(0, 0))
    # a left-to-right chain: its normal (right of a->b) points down, so rays from below hit it
    w.add_body(physics.Chain([(-5, 0), (0, 0), (5, 0)]), kind="static")
    assert w.ray_cast((1, -3), (1, 3), first=True)[0].fraction == 0.5
    assert w.ray_cast((1, 3), (1, -3)) == []
    w2 = physics.World(gravity=(0, 0))
    w2.add_body(physics.Segment((-5, 0), (5, 0)), kind="static")  # a plain segment is two-sided
    assert len(w2.ray_cast((1, 3), (1, -3))) == len(w2.ray_cast((1, -3), (1, 3))) == 1


def test_filters_select_fixtures_like_collisions():
    w, ground, ball, _ = _world()
    ball.fixtures[0].category = 0x4
    assert [h.body for h in w.ray_cast((0, 10), (0, -10))] == [ball, ground]  # default mask 0xFFFF sees 0x4
    assert [h.body for h in w.ray_cast((0, 10), (0, -10), mask=0x3)] == [ground]
    assert [h.body for h in w.ray_cast((0, 10), (0, -10), mask=0x4)] == [ball]
    ball.fixtures[0].mask = 0x2
    assert w.ray_cast((0, 10), (0, -10), mask=0x4) == []
    assert [h.body for h in w.ray_cast((0, 10), (0, -10), category=0x2, mask=0x4)] == [ball]


def test_queries_see_edits_and_steps():
    w, _, ball, _ = _world()
    assert w.query_point_all((0, 3))[0].body is ball
    ball.position = (-4, 3)
    assert w.query_point_all((0, 3)) == [] and w.query_point_all((-4, 3))[0].body is ball
    ball.velocity = (60, 0)
    w.step()  # 1 m in the step
    assert w.query_point_all((-4.0 + 1.0 + 0.99, 3))[0].body is ball
    other = w.add_body(physics.Polygon.box(1, 1), position=(10, 10))
    assert w.query_aabb((9, 9), (11, 11)) == other.fixtures
    w.remove(other)
    assert w.query_aabb((9, 9), (11, 11)) == []


def test_query_aabb_is_exact_not_by_boxes():
    w, _, ball, _ = _world()
    # the ball's box corner region (0.9, 3.9) is outside the disk: not returned
    assert w.query_aabb((0.8, 3.8), (1.0, 4.0)) == []
    assert w.query_aabb((0.6, 3.6), (1.0, 4.0))[0].body is ball   # |(0.6, 0.6)| < 1


def test_overlap_and_shape_cast():
    w, ground, ball, cap = _world()
    assert {f.body for f in w.overlap(physics.Circle(0.5), (0, 1.6))} == {ball}
    assert {f.body for f in w.overlap(physics.Polygon.box(1, 1), (0, 1.5), 0.0)} == {ball}  # touches at y=2
    hit = w.shape_cast(physics.Polygon.box(1, 1), (-8, 5), 0.0, (0, -10))
    assert hit.body is ground and hit.fraction == pytest.approx(0.45, abs=1e-9) and hit.normal == pytest.approx((0, 1))
    hit = w.shape_cast(physics.Circle(0.5), (5, 10), 0.0, (0, -10))
    assert hit.body is cap and hit.fraction == pytest.approx(0.7, abs=1e-9)   # 10 - 0.5 - 2.5 = 7 m
    assert hit.point == pytest.approx((5, 2.5)) and hit.normal == pytest.approx((0, 1))
    assert w.shape_cast(physics.Circle(0.5), (15, 10), 0.0, (0, 5)) is None


def test_ray_cast_many_shapes_and_refusals():
    w, ground, ball, _ = _world()
    H = w.ray_cast_many([[0, 10], [30, 10]], [[0, -10], [30, -10]])
    assert H["fixture"].tolist() == [ball.fixtures[0].id, -1] and H["body"].tolist() == [ball.id, -1]
    assert H["fraction"].tolist() == [0.3, -1.0]
    with pytest.raises(ValueError, match=r"starts\[1\]"):
        w.ray_cast_many([[0, 1], [np.nan, 0]], [[0, 0], [0, 0]])
    with pytest.raises(ValueError, match="start"):
        w.ray_cast((np.inf, 0), (0, 0))
    with pytest.raises(ValueError, match="upper"):
        w.query_aabb((1, 1), (0, 0))
    with pytest.raises(ValueError, match="shape"):
        w.overlap("box", (0, 0))


def test_empty_world_queries():
    w = physics.World()
    assert w.ray_cast((0, 0), (1, 1)) == [] and w.query_aabb((0, 0), (1, 1)) == []
    assert w.ray_cast_many(np.zeros((2, 2)), np.ones((2, 2)))["fixture"].tolist() == [-1, -1]
    assert w.shape_cast(physics.Circle(1), (0, 0), 0, (1, 0)) is None


@pytest.mark.parametrize("bad", [(math.nan, 0.0), (0.0, math.inf), (10 ** 400, 0), (0, -10 ** 400)])
def test_points_refused_whatever_their_form(bad):
    # tuples of plain floats and ints take a fast path in ray_cast/query_aabb; it must refuse as
    # the general validator does, naming the argument
    w, *_ = _world()
    with pytest.raises(ValueError, match="start"):
        w.ray_cast(bad, (0.0, 0.0))
    with pytest.raises(ValueError, match="upper"):
        w.query_aabb((0.0, 0.0), bad)
    with pytest.raises(ValueError, match="point"):
        w.query_point_all(list(bad))


def test_every_point_form_gives_the_same_hits():
    w, *_ = _world()
    forms = [((0, 10), (0, -10)), ((0.0, 10.0), (0.0, -10.0)), ([0, 10], [0, -10]),
             (np.array([0.0, 10.0]), np.array([0.0, -10.0])), ((np.float32(0), np.int64(10)), (0.0, -10.0))]
    ref = w.ray_cast(*forms[0])
    assert len(ref) == 2
    for p, e in forms[1:]:
        assert w.ray_cast(p, e) == ref
    assert w.query_aabb((-1, 2), (1, 4)) == w.query_aabb(np.array([-1.0, 2.0]), [1.0, 4.0])


def test_queries_pass_through_sensors():
    # Box2D v3.1: queries skip sensors; a ray through a trigger zone hits the box behind it
    w = physics.World(gravity=(0, 0))
    zone = w.add_body(physics.Polygon.box(2, 2), kind="static", position=(0, 0))
    zone.fixtures[0].sensor = True
    box = w.add_body(physics.Polygon.box(1, 1), position=(5, 0))
    [hit] = w.ray_cast((-5, 0), (10, 0))
    assert hit.body is box and hit.fraction == pytest.approx(9.5 / 15, abs=1e-12)  # its face at x = 4.5
    assert w.ray_cast_many([[-5.0, 0.0]], [[10.0, 0.0]])["body"][0] == box.id
    assert w.query_aabb((-1, -1), (1, 1)) == [] and w.query_point_all((0, 0)) == []
    assert w.overlap(physics.Circle(0.5), (0, 0)) == []
    assert w.shape_cast(physics.Circle(0.25), (-5, 0), 0.0, (10, 0)).body is box
