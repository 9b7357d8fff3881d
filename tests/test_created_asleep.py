"""Bodies created asleep (``add_body(awake=False)``, the format's ``"awake": false``), as Box2D v3
creates them with ``b2BodyDef.isAwake = false``: at rest, each in an island of its own, costing
nothing until touched, and woken contact by contact."""
import numpy as np
import pytest

import physics
from builders import ground, world
from physics.errors import SceneError
from physics.scene import scene_from_dict, scene_to_dict

BOX = physics.Polygon.box(0.4, 0.4)


def test_a_body_created_asleep_stays_put_until_woken():
    w = world(sleeping=True)  # gravity on: an awake body would fall
    b = w.add_body(BOX, position=(0.0, 5.0), awake=False)
    assert not b.awake
    for _ in range(30):
        w.step()
    assert not b.awake and b.position == (0.0, 5.0) and b.velocity == (0.0, 0.0)
    b.wake()
    w.step()
    assert b.awake and b.position[1] < 5.0


def test_touching_sleepers_wake_contact_by_contact():
    """A row of touching boxes created asleep: a box slid into its end wakes the row one
    contact at a time (each its own island), not as one island."""
    w = world(gravity=(0.0, 0.0), sleeping=True)
    row = [w.add_body(BOX, position=(0.4 * i, 0.0), awake=False) for i in range(12)]
    islands = {b._B.island[b._s] for b in row}
    assert len(islands) == len(row)
    hitter = w.add_body(BOX, position=(-1.0, 0.0), velocity=(20.0, 0.0))
    counts = []
    for _ in range(40):
        w.step()
        counts.append(sum(b.awake for b in row))
    first = next(k for k, c in enumerate(counts) if c)
    assert counts[first] < 4, f"the first touch woke {counts[first]} boxes at once"
    assert counts[-1] == len(row)  # the wave went down the row
    assert all(b >= a for a, b in zip(counts, counts[1:])) and hitter.awake


def test_created_asleep_is_ignored_while_sleeping_is_off():
    w = world(sleeping=False)
    assert w.add_body(BOX, awake=False).awake


@pytest.mark.parametrize("kw,says", [({"kind": "static"}, "only a dynamic body"),
                                     ({"kind": "kinematic"}, "only a dynamic body"),
                                     ({"velocity": (1.0, 0.0)}, "at rest"),
                                     ({"angular_velocity": 2.0}, "at rest")])
def test_what_cannot_be_created_asleep_is_refused_naming_awake(kw, says):
    w = world(sleeping=True)
    with pytest.raises(ValueError, match=f"^awake: .*{says}"):
        w.add_body(BOX, awake=False, **kw)
    assert len(w.bodies) == 0  # a refused add leaves nothing


def test_awake_must_be_a_bool():
    with pytest.raises(ValueError, match="^awake: must be True or False"):
        world(sleeping=True).add_body(BOX, awake="no")


def _scene(*bodies):
    return {"format": "stelkropp.scene", "version": 2, "world": {"gravity": [0.0, -10.0], "sleeping": True},
            "bodies": [{"shape": {"box": [0.4, 0.4]}, "position": [1.0 * i, 3.0], **b} for i, b in enumerate(bodies)]}


def test_the_scene_format_creates_bodies_asleep_each_alone():
    w = scene_from_dict(_scene({"awake": False}, {"awake": False}, {}, {"asleep": 7}, {"asleep": 7}))
    assert [b.awake for b in w.bodies] == [False, False, True, False, False]
    label = [int(b._B.island[b._s]) for b in w.bodies]
    assert label[0] != label[1] and label[3] == label[4] and label[3] not in label[:2]
    for _ in range(5):
        w.step()
    assert w.bodies[0].position == (0.0, 3.0) and w.bodies[2].position[1] < 3.0
    again = scene_from_dict(scene_to_dict(w))  # saved as sleeping islands, loaded asleep again
    assert [b.awake for b in again.bodies] == [False, False, True, False, False]


def test_awake_true_and_an_island_number_contradict():
    with pytest.raises(SceneError, match=r"bodies\[0\]\.awake"):
        scene_from_dict(_scene({"awake": True, "asleep": 3}))


def test_setting_the_gravity_it_has_wakes_nothing():
    w = world(sleeping=True)
    ground(w)
    b = w.add_body(BOX, position=(0.0, 0.2), awake=False)
    w.gravity = w.gravity
    assert not b.awake
    w.gravity = (0.0, -5.0)
    assert b.awake


def test_a_sleeping_wall_costs_what_its_awake_neighbour_does():
    """What the step does with 400 sleepers and one awake body: the same state as with the
    awake body alone (nothing of the wall moves, and the lone body's path is not changed)."""
    alone = world(sleeping=True)
    lone = alone.add_body(BOX, position=(-30.0, 0.0), velocity=(1.0, 2.0))
    w = world(sleeping=True)
    for i in range(20):
        for j in range(20):
            w.add_body(BOX, position=(0.4 * i, 0.4 * j), awake=False)
    mover = w.add_body(BOX, position=(-30.0, 0.0), velocity=(1.0, 2.0))
    wall = np.array([b.position for b in w.bodies[:400]])
    for _ in range(20):
        alone.step()
        w.step()
    assert mover.position == lone.position and mover.velocity == lone.velocity
    assert np.array_equal(wall, np.array([b.position for b in w.bodies[:400]]))
    assert w.info()["awake"] == 1


def _scene_of_sleepers(w):
    """A static ground, a wall created asleep, a box that falls and sleeps, and a kinematic body
    far off that keeps the steps running."""
    ground(w)
    for i in range(6):
        for j in range(4):
            w.add_body(BOX, position=(0.4 * i, 0.2 + 0.4 * j), awake=False)
    w.add_body(BOX, position=(-6.0, 3.0))
    w.add_body(BOX, kind="kinematic", position=(-15.0, 5.0), velocity=(0.0, 0.01))


def _boxes(w):
    s = w._store
    return (s.fixtures.view.aabb[:s.fixtures.n].copy(), s.verts.view.world[:s.verts.top].copy(),
            s.bodies.view.aabb[:s.bodies.n].copy(), w.state()["position"].copy())


def test_static_and_sleeping_geometry_kept_between_steps_is_exact():
    """The step keeps the boxes of static and sleeping bodies instead of computing them again.
    Beside a twin world made to compute every box every step (an edit each step), through
    falling asleep, a change of the speculative margin, a moved ground and a woken wall, every
    box and position stays bit for bit the same."""
    kept, full = world(sleeping=True), world(sleeping=True)
    for w in (kept, full):
        _scene_of_sleepers(w)

    def run(steps, edit=None):
        for _ in range(steps):
            for w in (kept, full):
                if edit:
                    edit(w)
                if w is full:
                    w._pipeline.invalidate()  # as any edit does: the next step computes every box
                w.step()
            assert all(np.array_equal(a, b) for a, b in zip(_boxes(kept), _boxes(full)))

    run(200)
    assert not kept.bodies[25].awake  # the fallen box sleeps; the kinematic body keeps stepping
    run(1, lambda w: setattr(w, "speculative_distance", 0.05))
    run(3)
    run(1, lambda w: setattr(w.bodies[0], "position", (0.0, -0.45)))  # the ground, under the sleepers
    run(3)
    before = [b.position for b in kept.bodies[1:25]]
    run(1, lambda w: w.add_body(BOX, position=(-0.6, 0.2), velocity=(3.0, 0.0)))
    run(60)
    assert [b.position for b in kept.bodies[1:25]] != before  # the hit woke the wall and moved it
