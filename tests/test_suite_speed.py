"""Box2D v3's benchmark suite timed beside Stelkropp (bench/suite_speed.py, issue 17). Structure
and honesty only (no timing asserts): every engine runs the same scene interleaved, ratios are
finite, every suite scene builds in Stelkropp with benchmarks.c's bodies and joints and its script
(events, drives) run on our side too, and NEEDS claims only what the core still lacks."""
import math

import pytest

import physics
from bench.report.suite_table import B1, B2, OURS, OURS2, PM, table_md
from bench.suite import LACKS, NEEDS, SUITE
from bench.suite.benchmarks import joint_grid, junkyard, large_pyramid, smash
from bench.suite.common import body, box, scene
from bench.suite.ragdoll import rain
from bench.suite_speed import _ours, _pymunk, run_scene
from physics.scene import scene_from_dict
from physics.errors import SceneError
from box2d_ref import box2d_v3
from physics import threads

# ours on two threads runs where numba can run two (World.threads)
OURS_2T = {OURS2} if threads.available() >= 2 else set()


def test_a_small_large_pyramid_runs_in_every_engine_interleaved():
    box2d_v3()  # Box2D v3 runs beside us here (skips, saying why, only without its sources)
    row = run_scene("large_pyramid", steps=41, chunk=10, warm=10, desc=large_pyramid(base=8))
    assert row["status"] == "ok" and row["steps_done"] == 41
    assert set(row["ms_step"]) == {OURS, B1, B2, PM} | OURS_2T  # ours with one thread and (here) with two
    for e in (B1, B2, PM, *OURS_2T):
        assert math.isfinite(row["ratio"][e]) and row["ratio"][e] > 0
    assert math.isfinite(row["box2d_two_thread_speedup"])
    if OURS_2T:
        assert all(math.isfinite(row["ratio_2t"][e]) and row["ratio_2t"][e] > 0 for e in (B1, B2))
        assert math.isfinite(row["two_thread_speedup"])
    else:
        assert "threads" in row["not_built"][OURS2]
    md = table_md([row])
    assert md[2].startswith("| large_pyramid | 37 | 41 |")


def test_a_joint_scene_is_timed_in_stelkropp_and_box2d():
    box2d_v3()  # Box2D v3 runs beside us here (skips, saying why, only without its sources)
    row = run_scene("joint_grid", steps=21, chunk=10, warm=10, desc=joint_grid(n=4))
    assert row["status"] == "ok" and OURS in row["ms_step"] and math.isfinite(row["ratio"][B1])


def test_rain_times_the_ragdolls_its_events_add_on_both_sides():
    box2d_v3()  # Box2D v3 runs beside us here (skips, saying why, only without its sources)
    # 3 event steps (0, 8, 16) of 25 ragdolls of 11 bodies: ours must time them, not the bare ground
    row = run_scene("rain", steps=21, chunk=10, warm=10, desc=rain(steps=21))
    assert row["status"] == "ok" and row["bodies_end"] == 1 + 3 * 25 * 11
    assert set(row["ms_step"]) == {OURS, B1, B2} | OURS_2T and "bench.events" in row["not_built"][PM]
    assert "1->826" in table_md([row])[2] and "no pymunk" in table_md([row])[2]


def test_junkyard_pusher_is_driven_to_its_target_on_our_side():
    desc = junkyard(columns=4, rows=2)
    sim = _ours(desc)
    pusher = sim.world.body("pusher")
    dt = sim.world.dt
    sim.before(1)  # from rest at x = 0: the velocity that reaches 60 sin(0.2 dt) in one step
    assert pusher.velocity[0] == pytest.approx(60.0 * math.sin(0.2 * dt) / dt, rel=1e-12)
    assert pusher.velocity[1] == 0.0 and pusher.angular_velocity == 0.0


def test_smash_wall_is_created_asleep_on_our_side_and_the_ram_moves():
    sim = _ours(smash(columns=4, rows=3))
    ram, wall = sim.world.bodies[0], sim.world.bodies[1:]
    assert not any(b.awake for b in wall)  # before any step, as Box2D creates them
    assert len({b._B.island[b._s] for b in wall}) == len(wall)  # each its own island, as in Box2D
    sim.step()
    assert ram.awake and ram.velocity == (40.0, 0.0) and not any(b.awake for b in wall)


def test_pymunk_creates_smash_wall_asleep_and_the_ram_wakes_it():
    pytest.importorskip("pymunk")  # a bench extra (.ci/run installs it)
    sim = _pymunk(smash(columns=4, rows=3))
    ram, wall = sim.bodies[0], sim.bodies[1:]
    assert not ram.is_sleeping and all(b.is_sleeping for b in wall)
    for _ in range(90):  # 45 m to go at 40 m/s: the impact comes at about step 69
        sim.step()
    assert not any(b.is_sleeping for b in wall) and wall[0].position.x > 30.0


def test_every_suite_scene_says_how_it_differs():
    assert set(NEEDS) == set(SUITE)
    claims = set(LACKS.values())
    assert all(d in claims for ds in NEEDS.values() for d in ds)  # only probed claims (next test)


@pytest.mark.parametrize("key,where,value", [("linear_damping", "body", {"linear_damping": 0.1}),
                                             ("hit_events", "shape", {"hit_events": True})])
def test_what_needs_claims_missing_is_still_missing(key, where, value):
    # the day the core grows the feature (a body/fixture attribute, a scene key), NEEDS must lose the line
    assert key in LACKS
    name = next(iter(value))
    target = {"body": physics.Body, "shape": physics.Fixture}[where]
    prop = getattr(target, name, None)
    assert prop is None or (isinstance(prop, property) and prop.fset is None)
    b = body(box(0.5, 0.5), 0.0, 0.0)
    (b if where == "body" else b["shape"]).update(value)
    with pytest.raises(SceneError, match="unknown key"):
        scene_from_dict(scene("probe", "", [b]))


# bodies, shapes (fixtures; a 360-point chain loop is 360) and joints shared/benchmarks.c creates,
# as tests/test_box2d_v3.py counts them on Box2D's side; rain: its ground and its first step's
# 25 ragdolls (11 bodies, 13 shapes, 10 joints each), added by the events script
OUR_COUNTS = {"large_pyramid": (5051, 5051, 0), "many_pyramids": (22001, 22020, 0), "smash": (9601, 9601, 0),
              "joint_grid": (10000, 10000, 19800), "spinner": (6078, 6076 + 1 + 360, 1), "tumbler": (2026, 2029, 1),
              "washer": (8101, 8140, 0), "junkyard": (8002, 8262, 0), "compounds": (3001, 6282, 0),
              "rain": (1 + 25 * 11, 2505 + 25 * 13, 25 * 10)}


@pytest.mark.parametrize("name", sorted(SUITE))
def test_every_suite_scene_builds_in_stelkropp(name):
    sim = _ours(rain(steps=1) if name == "rain" else SUITE[name]())
    if name == "rain":
        sim.before(0)
    w = sim.world
    assert (len(w.bodies), sum(len(b.fixtures) for b in w.bodies), len(w.joints)) == OUR_COUNTS[name]
