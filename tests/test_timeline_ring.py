"""app.timeline without a window: the ring's bound, its cadence in steps, scrubbing back and
playing on (bit-identical to an uninterrupted run), and what clears or holds it."""
from __future__ import annotations

import pytest

import physics
from app.timeline import Timeline


def world():
    w = physics.World(sleeping=False)
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    w.add_body(physics.Circle(0.5), position=(0, 3), restitution=0.5)
    return w


def play(tl, w, steps):
    for _ in range(steps):
        w.step()
        tl.record(w)


def test_ring_cadence_bound_scrub_and_play_on():
    w, tl = world(), Timeline(interval=0.25, span=1.0)      # 60 Hz: one snapshot every 15 steps, 5 kept
    tl.record(w)
    play(tl, w, 150)                                        # 2.5 s
    assert len(tl) == 5 and tl.entries.maxlen == 5
    assert [round(t / w.dt) for t in tl.times()] == [90, 105, 120, 135, 150]
    ref = world()
    for _ in range(180):
        ref.step()
    assert tl.scrub(w, 1.8) == pytest.approx(105 * w.dt) and w.steps == 105 and tl.cursor == 1
    play(tl, w, 75)                                        # the snapshots after step 105 go
    assert [round(t / w.dt) for t in tl.times()] == [120, 135, 150, 165, 180]
    assert w.bodies[1].position == ref.bodies[1].position and tl.cursor is None


def test_topology_edit_clears_tool_joint_holds():
    w, tl = world(), Timeline()
    tl.record(w)
    play(tl, w, 30)
    ball = w.bodies[1]
    j = w.add_joint("mouse", ball, None, target=(0.0, 3.0))
    assert not tl.watch(w, 1, transient=True) and tl.held and tl.scrub(w, 0.0) is None and len(tl) == 3
    w.remove(j)
    assert not tl.watch(w, 2) and not tl.held and tl.scrub(w, 0.0) == 0.0
    w.add_body(physics.Circle(0.2), position=(3, 3))
    assert tl.watch(w, 3) and len(tl) == 0 and tl.cleared == 1


def test_byte_budget_limits_the_ring():
    from app.timeline import nbytes
    w = world()
    size = nbytes(w.snapshot())
    assert size > 1000                                     # the arrays are counted
    tl = Timeline(interval=0.25, span=60.0, budget=3 * size + 1)
    tl.record(w)
    play(tl, w, 150)
    assert tl.capacity == 3 and len(tl) == 3 and [round(t / w.dt) for t in tl.times()] == [120, 135, 150]
