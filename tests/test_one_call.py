"""The step as one compiled call (physics/step/soft_driver.py) against the pipeline's stages.

Both paths run the same kernels in the same order, so a world stepped through the driver must
end bit for bit where the same world stepped through the pipeline ends: every field of every
body, and the contact and joint impulses.  The scenes make the driver grow each array it may
find short (pairs, contact rows, the touching sets), switch to the narrow phase's whole kernel,
rebuild the joint system when a joined body changes kind, and sleep.
"""
import math
from pathlib import Path

import numpy as np
import pytest

import physics
from physics.scene import scene_from_dict
from bench.small_descs import small
from physics.constraints.colouring import LANES
from physics.step.soft_driver import S_SWEEP

ROOT = Path(__file__).resolve().parent.parent


def _pile(n=40):
    """n boxes created on top of each other: n (n - 1) / 2 + n pairs at once (> 256, the pair
    buffer's and the contact table's first size)."""
    w = physics.World(gravity=(0, -10))
    w.add_body(physics.Polygon.box(10, 0.5), position=(0, -0.25), kind="static")  # top at y = 0
    for i in range(n):
        w.add_body(physics.Polygon.box(0.5, 0.5), position=(0.01 * i, 0.6 + 0.02 * i))
    return w


def _rounded():
    """A capsule and a disc on a box: pairs the narrow phase's lean kernel leaves to the whole one."""
    w = physics.World(gravity=(0, -10))
    w.add_body(physics.Polygon.box(10, 0.5), position=(0, -0.25), kind="static")  # top at y = 0
    w.add_body(physics.Capsule((-0.5, 0), (0.5, 0), 0.2), position=(0, 0.19))
    w.add_body(physics.Circle(0.3), position=(2, 0.29))
    w.add_body(physics.Polygon.box(0.5, 0.5, radius=0.05), position=(-2, 0.29))
    return w


def _swept_pile():
    """The pile with the sweep broad phase chosen: it grows the pairs (and the sweep's own pair
    scratch with them) as the brute force pile does."""
    w = _pile()
    w.broadphase = "sweep"
    return w


def _sleeping_wall():
    """A wall created asleep (Box2D's smash sample, small) and a ball thrown at it: the driver's
    lists of moving bodies (step/active.py), its index of the resting boxes and the wall's waking
    box by box (broadphase/resting_index.py) against the pipeline, which loops over every body."""
    w = physics.World(gravity=(0, -10))
    w.broadphase = "sweep"
    w.add_body(physics.Polygon.box(40, 1), position=(0, -0.5), kind="static")
    for i in range(10):
        for j in range(8):
            w.add_body(physics.Polygon.box(0.5, 0.5), position=(2 + 0.5 * i, 0.25 + 0.5 * j), awake=False)
    w.add_body(physics.Circle(0.4), position=(-3, 1.5), velocity=(12, 0), density=20)
    return w


SCENES = {
    "box": lambda: scene_from_dict(small("box")),
    "stack5": lambda: scene_from_dict(small("stack5")),
    "pendulum": lambda: scene_from_dict(small("pendulum")),
    "chain10": lambda: scene_from_dict(small("chain10")),
    "cradle5": lambda: scene_from_dict(small("cradle5")),
    "pile40": _pile,
    "rounded": _rounded,
    "pile40_sweep": _swept_pile,
    "sleeping_wall": _sleeping_wall,
    # 132 fixtures: the automatic broad phase is the sweep; springs, circles and polygons
    "default": lambda: physics.load_scene(ROOT / "scenes" / "default.json"),
}


def _run(make, driver: bool, steps: int, edit=None):
    """``steps`` steps of a new world through the driver or the pipeline; the number of contact
    begin events seen on the way is kept as ``w.begins``."""
    w = make()
    w._pipeline.one_call.enabled = driver
    w.begins = 0
    for k in range(steps):
        if edit is not None:
            edit(w, k)
        w.step()
        w.begins += len(w.contact_events().begin)
    return w


def _same(a, b):
    sa, sb = a._store, b._store
    n = sa.bodies.n
    for name, col in sa.bodies.arrays.items():
        np.testing.assert_array_equal(col[:n], sb.bodies.arrays[name][:n], err_msg=f"body field {name}")
    nc = sa.contacts.n
    assert nc == sb.contacts.n
    np.testing.assert_array_equal(sa.contacts.cur.jn[:nc], sb.contacts.cur.jn[:nc])
    np.testing.assert_array_equal(sa.contacts.cur.key[:nc], sb.contacts.cur.key[:nc])
    nj = sa.joints.n
    np.testing.assert_array_equal(sa.joints.view.impulse[:nj], sb.joints.view.impulse[:nj])
    assert a.steps == b.steps and a.time == b.time and a.begins == b.begins
    ta, tb = a._pipeline.events.contacts, b._pipeline.events.contacts
    np.testing.assert_array_equal(ta.keys[:ta.n], tb.keys[:tb.n])  # the touching sets


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_driver_steps_bit_for_bit_as_the_pipeline(scene):
    a = _run(SCENES[scene], True, 120)
    assert a._pipeline.one_call.P is not None, "the driver did not run this world"
    b = _run(SCENES[scene], False, 120)
    assert b._pipeline.one_call.P is None
    _same(a, b)


def test_the_driver_runs_the_sweep_with_its_own_scratch():
    w = _run(SCENES["default"], True, 3)
    assert physics.collision.broadphase.resolve(w.broadphase, w._store.fixtures.n) == "sweep"
    oc = w._pipeline.one_call
    assert oc.P is not None and oc.S[S_SWEEP] == 1
    assert oc.sweep[0][0] == w._store.fixtures.n  # the kept order's [n, axis]: the driver swept
    brute = _run(_pile, True, 1)._pipeline.one_call
    swept = _run(_swept_pile, True, 1)._pipeline.one_call
    assert brute.S[S_SWEEP] == 0 and len(brute.sweep[1]) == 0 and swept.S[S_SWEEP] == 1
    assert brute._call is swept._call  # one compiled driver for both broad phases


def test_driver_grows_what_it_found_short():
    w = _run(_pile, True, 3)
    assert w._pipeline.npairs > 256 and w._store.contacts.n > 256
    assert w._store.contacts.capacity >= w._store.contacts.n


def test_driver_grows_the_coloured_blocks():
    """The pile starts with every box touching many others: colours run out and each overflow
    manifold takes a block of its own.  The blocks (the mode's, shared by the process's worlds)
    start at one block here, so the driver finds them short and they grow."""
    w = _pile()
    w._mode.coloured.force[0] = 0  # (the mode's scratch is the process's: a test may have set it)
    w._mode.coloured._wide(LANES)
    first = len(w._mode.coloured.GA)
    _run(lambda: w, True, 3)
    oc = w._pipeline.one_call
    assert oc.P is not None and oc.wide is not None, "the driver did not run the coloured world"
    assert len(w._mode.coloured.GA) > first
    assert oc.wide[6] is w._mode.coloured.GA  # the pack holds the grown blocks


def test_driver_switches_to_the_whole_narrow_phase():
    w = _run(_rounded, True, 2)
    assert w._store.contacts.full and w._store.contacts.n == 3


def test_joined_body_changing_kind_rebuilds_the_joint_system():
    def edit(w, k):
        if k == 30:
            w.bodies[0].kind = "static"  # the pendulum's bob: its joint no longer moves anything
        if k == 60:
            w.bodies[0].kind = "dynamic"
    a = _run(SCENES["pendulum"], True, 120, edit)
    b = _run(SCENES["pendulum"], False, 120, edit)
    _same(a, b)


def test_sleeping_and_waking_match_the_pipeline():
    def make():
        w = scene_from_dict(small("stack5"))
        w.sleeping = True
        return w

    def edit(w, k):
        if k == 250:
            w.bodies[-1].apply_impulse((2.0, 0.0))
    a = _run(make, True, 400, edit)
    b = _run(make, False, 400, edit)
    _same(a, b)
    assert a._pipeline.n_awake == b._pipeline.n_awake


def test_an_island_put_to_sleep_in_the_driver_wakes_whole():
    """A stack falls asleep as one island while a ball rolls towards it; the ball's contact wakes
    the island along the cycle the driver's sleep update linked (step/active.py), not a scan:
    every step the same bits as the pipeline's scan, the stack asleep before and awake after."""
    def make():
        w = physics.World(gravity=(0, -10))
        w.add_body(physics.Polygon.box(60, 1), position=(0, -0.5), kind="static")
        for i in range(4):
            w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5 + 1.0 * i))
        w.add_body(physics.Circle(0.3), position=(-18, 0.3), velocity=(8, 0), density=5)
        return w

    seen = {}

    def edit(w, k):
        if k in (120, 299):
            seen[k] = [b.awake for b in w.bodies[1:5]]
    a = _run(make, True, 300, edit)
    b = _run(make, False, 300, edit)
    _same(a, b)
    assert seen[120] == [False] * 4 and seen[299] == [True] * 4


def test_driver_profile_splits_the_step_into_its_stages():
    w = _run(SCENES["stack5"], True, 10)
    p = w.profile
    stages = ("begin", "broadphase", "narrowphase", "solve", "islands", "finish")
    assert all(p[s] >= 0.0 for s in stages)
    assert math.isclose(sum(p[s] for s in stages), p["step"], rel_tol=1e-6)
    assert p["solve"] > 0.0 and p["narrowphase"] > 0.0


def test_worlds_the_driver_leaves_to_the_pipeline():
    w = scene_from_dict(small("stack5"))
    w.solver = "sequential_impulse"
    w.step()
    assert w._pipeline.one_call.P is None
    w.solver = "soft_step"
    w.step()
    assert w._pipeline.one_call.P is not None
    w.bodies[0].fixtures[0].sensor = True  # a sensor (the static ground): the pipeline's events stage
    w.step()
    assert w._pipeline.one_call.P is None


def test_a_world_waits_for_its_driver_without_compile_on_demand(monkeypatch):
    """With ``compile_on_demand`` off (the sandbox) a world whose driver is not compiled steps
    through the pipeline's stages, and through the driver from the step after it is compiled:
    the same bits as a world stepped through the pipeline all along."""
    from physics.step import one_call
    _run(SCENES["chain10"], True, 1)  # the driver for this pack type, compiled in this process

    class NotCompiled:
        overloads = {}
    compiled = one_call.soft_world_step
    was = one_call.compile_on_demand(False)
    try:
        monkeypatch.setattr(one_call, "soft_world_step", NotCompiled)

        def edit(w, k):
            if k == 40:  # compiled (by the sandbox's compile unit) while the world steps
                monkeypatch.setattr(one_call, "soft_world_step", compiled)
            oc = w._pipeline.one_call  # (the state the step before this one left)
            if k >= 1:
                assert (oc.P is not None) == (k > 40), k
                assert (oc._waiting is not None) == (k <= 40), k
        a = _run(SCENES["chain10"], True, 120, edit)
    finally:
        one_call.compile_on_demand(was)
    b = _run(SCENES["chain10"], False, 120)
    _same(a, b)


def test_the_pack_lends_its_fields_to_the_driver_in_order():
    """pack.call_with_fields passes the pack's fields by position: _drive's parameters must be
    pack.FIELDS in order, or two arrays of one type (the touching sets' spares, the contact
    tables) would silently trade places."""
    import inspect

    from physics.step.pack import FIELDS
    from physics.step.soft_driver import _drive

    assert tuple(inspect.signature(_drive.py_func).parameters) == FIELDS


def test_stepping_through_the_driver_keeps_no_reference():
    """The driver borrows the pack's arrays (no reference counting while stepping).  None is
    released early: after many steps each array the store holds has the Python references it
    had before.  None is kept: once the world is gone, only this test refers to them.  A
    pendulum and a pile cover the joint and contact arrays."""
    import gc
    import sys

    for make in (SCENES["pendulum"], _pile):
        w = make()
        w.step()
        assert w._pipeline.one_call.P is not None
        s = w._store

        def held():  # the arrays the store holds now (a grown table replaces its arrays)
            return {id(a): a for a in (*s.bodies.arrays.flat, *s.fixtures.arrays.flat, *s.contacts.cur_cols.flat,
                                       *s.contacts.prev_cols.flat, *(s.joints.arrays.flat if s.joints.n else ()))}

        for _ in range(30):  # past the steps that grow the pile's pair and contact arrays
            w.step()
        before = {k: sys.getrefcount(a) for k, a in held().items()}
        for _ in range(50):
            w.step()
        after = {k: sys.getrefcount(a) for k, a in held().items()}
        assert after.keys() == before.keys() and len(after) >= 10
        assert after == before
        arrays = list(held().values())
        del w, s
        gc.collect()
        assert [sys.getrefcount(a) - 2 for a in arrays] == [1] * len(arrays)  # (the list's own)


@pytest.mark.parametrize("case", [528, 7958, 12570])
def test_a_switch_into_soft_step_with_joints_steps_as_the_pipeline(case):
    """Worlds of the world fuzzer (bench/fuzz, seed 1) that switch from another mode into
    soft_step with joints: the driver's steps are the pipeline's, bit for bit, up to the end or
    the first refused step.  Before the driver borrowed the pack's arrays, its steps after such a
    switch parted from the pipeline's (14 of 20,000 fuzz cases)."""
    import random

    from bench.fuzz.worlds import build
    from physics.errors import SimulationError

    runs = []
    for driver in (True, False):
        plan = build(random.Random(f"world:1:{case}"))
        w = plan.world
        w._pipeline.one_call.enabled = driver
        w.begins = 0
        for k in range(plan.steps):
            if k == plan.switch_at:
                w.solver = plan.switch_to
            try:
                w.step()
            except SimulationError:
                break
        runs.append(w)
    assert plan.switch_to == "soft_step" and plan.switch_at < runs[0].steps and len(runs[0].joints) > 0
    assert runs[0]._pipeline.one_call.P is not None, "the driver did not run this world"
    _same(*runs)
