"""bench/reliability/coherence.py: the count of pushing contact points whose impulse is carried.

The tool is a measure for issue 18 (what a solver change does to warm starting), so these tests
check that it counts right: a resting stack keeps every impulse (the narrow phase makes the same
points from the same features every step), a pair pulled apart is counted as gone, and a
point remade from other features is counted as lost.
"""
from __future__ import annotations

import physics
from bench.reliability.coherence import compare, measure, pushing_points

from builders import ground, world


def _stack(n=3):
    w = world()
    ground(w)
    bodies = [w.add_body(physics.Polygon.box(1.0, 1.0), position=(0.0, 0.5 + i), friction=0.6) for i in range(n)]
    return w, bodies


def test_a_resting_stack_carries_every_pushing_point():
    w, _ = _stack()
    rows = measure(w, 60)[10:]  # after the first contact steps
    assert all(r.pushing >= 6 for r in rows)  # three face contacts, two points each
    assert all(r.carried == r.pushing and r.lost_fraction == 0.0 for r in rows)


def test_a_pair_pulled_apart_counts_as_gone():
    w, bodies = _stack(1)
    for _ in range(20):
        w.step()
    before = pushing_points(w)
    assert len(before[0]) == 2
    bodies[0].position = (0.0, 10.0)
    w.step()
    r = compare(before, pushing_points(w), 21)
    assert (r.pushing, r.carried, r.new_feature, r.pair_gone) == (2, 0, 0, 2)
    assert r.lost_fraction == 1.0


def test_a_point_remade_from_other_features_counts_as_lost():
    prev = ({(7, 1): 0.5, (7, 2): 0.25, (9, 1): 1.0}, {7, 9})
    cur = ({(7, 1): 0.5, (7, 3): 0.25}, {7})
    r = compare(prev, cur, 1)
    assert (r.pushing, r.carried, r.new_feature, r.pair_gone) == (3, 1, 1, 1)
    assert abs(r.lost_fraction - 2 / 3) < 1e-12
