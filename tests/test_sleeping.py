"""Islands and sleeping (issue 5): rest -> sleep; touch, edit, springs, or the switch -> wake."""
import numpy as np
import pytest

import physics
from builders import ground, positions, stack, world

SOLVERS = ("soft_step", "sequential_impulse")


def ground_world(solver="soft_step", sleeping=True):
    w = world(solver, sleeping=sleeping)
    ground(w)
    return w


def run_until_asleep(w, bodies, max_steps=600):
    for k in range(max_steps):
        w.step()
        if not any(b.awake for b in bodies):
            return k + 1
    raise AssertionError(f"still awake after {max_steps} steps: {[b.velocity for b in bodies]}")


@pytest.mark.parametrize("solver", SOLVERS)
def test_box_settles_and_sleeps(solver):
    w = ground_world(solver)
    b = w.add_body(physics.Polygon.box(1, 1), position=(0, 1.0))
    steps = run_until_asleep(w, [b])
    assert steps * w.dt >= w.time_to_sleep
    assert b.velocity == (0.0, 0.0) and b.angular_velocity == 0.0
    p = b.position
    for _ in range(60):
        w.step()
    assert b.position == p and not b.awake
    assert w.info()["awake"] == 0


@pytest.mark.parametrize("solver", SOLVERS)
def test_sleeping_pile_wakes_when_hit(solver):
    w = ground_world(solver)
    pile = stack(w, 4)
    run_until_asleep(w, pile)
    rest = [b.position for b in pile]
    falling = w.add_body(physics.Polygon.box(1, 1), position=(0.2, 8.0))
    woke = False
    for _ in range(120):
        w.step()
        if all(b.awake for b in pile):  # the island wakes as a whole
            woke = True
            break
    assert woke, "the pile did not wake when the box landed on it"
    assert falling.position[1] > 4.0 - 0.1  # it landed on the pile, not through it
    run_until_asleep(w, pile + [falling], max_steps=900)
    for b, p in zip(pile, rest):
        assert np.hypot(*(np.subtract(b.position, p))) < 0.1


@pytest.mark.parametrize("edit", ["position", "velocity", "angular_velocity", "angle"])
def test_edit_wakes_island(edit):
    w = ground_world()
    pile = stack(w, 3)
    run_until_asleep(w, pile)
    b = pile[1]
    value = {"position": (b.position[0] + 0.01, b.position[1]), "velocity": (0.5, 0.0),
             "angular_velocity": 0.1, "angle": 0.01}[edit]
    setattr(b, edit, value)
    assert all(p.awake for p in pile), "an edited body wakes its whole island"
    w.step()
    assert all(p.awake for p in pile)


def test_spring_to_awake_body_wakes_island():
    w = ground_world()
    pile = stack(w, 3)
    run_until_asleep(w, pile)
    other = w.add_body(physics.Polygon.box(1, 1), position=(5, 3))
    assert not pile[0].awake
    w.add_spring(pile[2], other, stiffness=50.0)
    assert all(b.awake for b in pile)
    for _ in range(30):
        w.step()
    assert pile[2].awake  # held awake by the spring to a moving body


def test_spring_keeps_awake_body_waking_sleeper():
    """A spring from a sleeping island to an awake body (added while both were awake) wakes it."""
    w = ground_world()
    pile = stack(w, 2)
    other = w.add_body(physics.Polygon.box(1, 1), position=(6, 0.5))
    w.add_spring(pile[1], other, stiffness=1.0, damping=5.0)
    run_until_asleep(w, pile + [other], max_steps=900)
    other.velocity = (0.0, 3.0)  # edit wakes other; the spring must wake the pile at the next step
    w.step()
    assert all(b.awake for b in pile)


def test_sleeping_off_wakes_all():
    w = ground_world()
    pile = stack(w, 3)
    run_until_asleep(w, pile)
    w.sleeping = False
    assert all(b.awake for b in pile)
    for _ in range(60):
        w.step()
    assert all(b.awake for b in pile)


def test_sleeping_pairs_skipped_by_broadphase():
    w = ground_world()
    pile = stack(w, 4)
    run_until_asleep(w, pile)
    # something awake elsewhere, resting on the same ground, keeps the step running
    w.add_body(physics.Polygon.box(1, 1), position=(10, 0.5))
    w.step()
    awake = w.state()["awake"]
    dyn = np.array([b.kind == "dynamic" for b in w.bodies])
    # the broad phase's pair list has no public accessor: read it from the pipeline (storage slots
    # are body order here, nothing was removed)
    pairs = w._pipeline._pairs[: w._pipeline.npairs]
    for i, j in pairs:
        assert awake[i] or awake[j], "a pair of two sleeping bodies reached the narrow phase"
        assert not (not awake[i] and not dyn[j]) and not (not awake[j] and not dyn[i])
    # the pile's pairs (box-box, box-ground) are gone; the awake box's pair with the ground is there
    assert {tuple(sorted(map(int, p))) for p in pairs} == {(0, 5)}
    assert w.info()["awake"] == 1
    assert len(w.bodies) == 6


def test_everything_asleep_costs_nothing():
    w = ground_world()
    pile = stack(w, 3)
    run_until_asleep(w, pile)
    steps = w.steps
    x = positions(w)
    for _ in range(100):
        w.step()
    assert w.steps == steps + 100
    assert np.array_equal(x, positions(w))


@pytest.mark.parametrize("solver", SOLVERS)
def test_sleeping_body_never_keeps_velocity(solver):
    """A body pushed by a speculative contact (the hitter closes the gap during the step) wakes
    at once; it never sits asleep with the velocity the impulse gave it."""
    w = ground_world(solver)
    target = w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5))
    run_until_asleep(w, [target])
    hitter = w.add_body(physics.Polygon.box(1, 1), position=(-1.3, 0.5), velocity=(30.0, 0.0))
    for _ in range(30):
        w.step()
        if not target.awake:
            assert target.velocity == (0.0, 0.0) and target.angular_velocity == 0.0
    assert target.position[0] > 0.2, "the hit moved the sleeping box"
    assert hitter.position[0] < target.position[0]
