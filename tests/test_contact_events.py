"""Contact events (issue 15): begin / end / hit with the approach speed, paired exactly across
sleeping, removal mid-contact and solver-mode switches; replaced each step; snapshots."""
import math

import numpy as np

import pytest

import physics
from tests.event_pairs import Pairing, touching

MODES = ["soft_step", "sequential_impulse", "impulse", "penalty", "hybrid"]
G = 9.81


def _drop(solver, h=10.0):
    w = physics.World(solver=solver, gravity=(0, -G))
    ground = w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    box = w.add_body(physics.Polygon.box(1, 1), position=(0, h + 0.5))  # bottom h above the ground
    return w, ground.fixtures[0], box.fixtures[0]


@pytest.mark.parametrize("solver", MODES)
def test_a_dropped_box_begins_and_hits_at_sqrt_2gh(solver):
    """Fall from h = 10 m: v = sqrt(2 g h) = 14.0 m/s at impact.  The speed before the impact
    step's solve lags it by at most g dt = 0.16 m/s (1.2 %) and leads the discrete fall
    otherwise, so 1 % is the bound a step-aligned measure meets."""
    w, ground, box = _drop(solver)
    begins, ends, hits = [], [], []
    for _ in range(150):
        w.step()
        ev = w.contact_events()
        begins += ev.begin
        ends += ev.end
        hits += ev.hit
    v = math.sqrt(2 * G * 10.0)
    # penalty springs throw the box up a little (it leaves and lands again): paired, ending touching
    assert len(begins) == len(ends) + 1 and (len(begins) == 1 or solver == "penalty")
    e = begins[0]
    assert (e.fixture_a, e.fixture_b) == (ground, box)
    assert e.normal == pytest.approx((0.0, 1.0))
    assert e.approach_speed == pytest.approx(v, rel=0.01)
    # the point is midway across the start-of-step gap, which is at most one step's fall (v dt)
    assert -0.01 < e.point[1] <= v / 60 / 2 + 0.01 and abs(e.point[0]) <= 0.5 + 1e-9
    assert hits and hits[0].approach_speed == pytest.approx(v, rel=0.01)
    assert all(h.approach_speed > w.hit_event_threshold for h in hits)


def test_hit_threshold_filters_hits_and_validates():
    w, ground, box = _drop("soft_step", h=0.02)  # lands at ~0.6 m/s: below the default 1 m/s
    assert w.hit_event_threshold == 1.0
    hits = []
    for _ in range(30):
        w.step()
        hits += w.contact_events().hit
    assert hits == []
    for bad in (-1.0, math.nan, math.inf, "1"):
        with pytest.raises(ValueError, match="hit_event_threshold"):
            w.hit_event_threshold = bad
    w2, _, _ = _drop("soft_step", h=0.02)
    w2.hit_event_threshold = 0.3
    got = []
    for _ in range(30):
        w2.step()
        got += w2.contact_events().hit
    assert len(got) >= 1 and got[0].approach_speed == pytest.approx(math.sqrt(2 * G * 0.02), rel=0.3)


def test_events_are_replaced_by_the_next_step_and_a_sleeping_world_has_none():
    w, ground, box = _drop("soft_step", h=0.5)
    n = 0
    while not w.contact_events().begin:
        w.step()
        n += 1
        assert n < 60
    w.step()
    assert w.contact_events().begin == [] and w.contact_events().end == []
    for _ in range(120):
        w.step()
    assert not box.body.awake  # the whole world sleeps: steps are skipped, no events, still touching
    assert w.contact_events() == physics.ContactEvents([], [], [])


def test_pairing_across_sleep_with_the_rest_of_the_world_awake():
    w, ground, box = _drop("soft_step", h=0.5)
    far = w.add_body(physics.Circle(0.3), position=(8, 60))  # falls for 3.5 s: steps keep running
    log = Pairing()
    slept = False
    for _ in range(180):
        w.step()
        log.contacts(w)
        slept |= not box.body.awake
    assert slept and far.awake
    assert (log.begins, log.ends) == (1, 0)
    assert log.open == {(ground.id, box.id)}


@pytest.mark.parametrize("asleep", [False, True])
def test_removing_a_body_mid_contact_ends_its_contacts_once(asleep):
    w, ground, box = _drop("soft_step", h=0.5)
    w.add_body(physics.Circle(0.3), position=(8, 60))
    top = w.add_body(physics.Polygon.box(0.5, 0.5), position=(0, 1.3))  # lands on the box
    log = Pairing()
    for _ in range(150 if asleep else 40):
        w.step()
        log.contacts(w)
    assert asleep != box.body.awake
    assert log.open == {(ground.id, box.id), (box.id, top.fixtures[0].id)}
    w.remove(box.body)
    w.step()
    ev = w.contact_events()
    assert sorted((a.id, b.id) for a, b in ev.end) == sorted(log.open)
    assert not any(a.alive and b.alive for a, b in ev.end)
    log.contacts(w)
    for _ in range(60):  # top falls onto the ground: one new begin
        w.step()
        log.contacts(w)
    # top landed on the ground (asleep by now: world.contacts() no longer lists it, the events do)
    assert (ground.id, top.fixtures[0].id) in log.open and abs(top.position[1] - 0.25) < 0.01


def test_removing_the_last_body_ends_its_contacts():
    w, ground, box = _drop("soft_step", h=0.2)
    for _ in range(30):
        w.step()
    w.remove(box.body)
    w.remove(ground.body)
    w.step()
    assert w.contact_events().end == [(ground, box)]


def test_pairing_across_solver_switches_of_every_mode():
    w = physics.World()
    ground = w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    for k in range(3):
        w.add_body(physics.Polygon.box(1, 1), position=(0.1 * k, 0.5 + 1.05 * k))
    log = Pairing()
    for _ in range(60):
        w.step()
        log.contacts(w)
    settled = set(log.open)
    assert len(settled) == 3 and settled == touching(w)
    for mode in MODES[1:] + MODES[:1]:
        w.solver = mode
        for _ in range(40):
            w.step()
            log.contacts(w)
        assert log.open == touching(w), mode
    assert log.open == settled  # the stack never came apart: no contact ended on a switch
    assert ground.fixtures[0].id in {a for a, _ in log.open}


def test_a_restored_snapshot_replays_the_same_events():
    w, ground, box = _drop("soft_step", h=1.0)
    ball = w.add_body(physics.Circle(0.3), position=(0.2, 4))
    for _ in range(20):
        w.step()
    snap = w.snapshot()

    def record():
        out = []
        for _ in range(90):
            w.step()
            ev = w.contact_events()
            out.append(([(e.fixture_a.id, e.fixture_b.id, e.approach_speed) for e in ev.begin],
                        [(a.id, b.id) for a, b in ev.end], [(e.fixture_a.id, e.approach_speed) for e in ev.hit]))
        return out
    first = record()
    assert sum(len(b) for b, _, _ in first) >= 2  # box on ground, ball on box or ground
    w.restore(snap)
    assert w.contact_events() == physics.ContactEvents([], [], [])  # the step before restore: cleared
    assert record() == first


def _two_drops(gap):
    """Two boxes dropped 0.5 m, the second ``gap`` higher, and a free circle far off."""
    w, ground, box = _drop("soft_step", h=0.5)
    w.add_body(physics.Polygon.box(1, 1), position=(3, 1.0 + gap))
    far = w.add_body(physics.Circle(0.1), position=(-40, 5))
    return w, far


def _seen(ev):
    """An event list as fixture ids: comparable across two worlds built alike."""
    return ([(e.fixture_a.id, e.fixture_b.id, e.approach_speed) for e in ev.begin],
            [(e.fixture_a.id, e.fixture_b.id) for e in ev.end])


def _landings(gap, steps=40):
    w, _ = _two_drops(gap)
    seq = []
    for _ in range(steps):
        w.step()
        seq.append(_seen(w.contact_events()))
    return [i for i, s in enumerate(seq) if s[0]], seq


def test_a_refused_step_leaves_the_last_events_standing():
    """The step's touching merge runs before the step is accepted (frame.end_step).  A refused
    step (a body's kinetic energy overflows: not finite, reverted) must leave the last step's
    begins in place, although in it the second box would have begun; the run then goes on
    exactly as one without the refused step."""
    gap = next(g / 1000 for g in range(5, 200, 5)
               if len(b := _landings(g / 1000)[0]) == 2 and b[1] == b[0] + 1)  # box 2 lands a step later
    (first, second), seq = _landings(gap)
    w, far = _two_drops(gap)
    for _ in range(second):
        w.step()
    assert _seen(w.contact_events()) == seq[first] and seq[first][0]
    far.apply_impulse((1e300, 0.0))  # 1/2 m v^2 overflows: the step is refused
    with pytest.raises(physics.SimulationError):
        w.step()
    assert _seen(w.contact_events()) == seq[first]
    far.velocity = (0.0, 0.0)
    for i in range(second, len(seq)):
        w.step()
        assert _seen(w.contact_events()) == seq[i]


def test_contact_depths_are_the_contacts_depths():
    """``contact_depths()`` is the numpy readout of ``[c.depth for c in contacts()]``: same
    rows, same order, the same deepest-point depth (the sandbox's stats read it every frame)."""
    w = physics.World(sleeping=False)
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    for i in range(6):
        for j in range(6 - i):
            w.add_body(physics.Polygon.box(1, 1), position=(j - 2.5 + 0.5 * i, 0.5 + i), angle=0.01 * j)
    w.add_body(physics.Circle(0.5), position=(6, 3))    # apart: speculative rows, not touching
    assert len(w.contact_depths()) == 0
    for _ in range(40):
        w.step()
    want = [c.depth for c in w.contacts()]
    got = w.contact_depths()
    assert len(want) >= 20 and got.dtype == np.float64
    assert got.tolist() == want
