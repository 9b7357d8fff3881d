"""Box2D v3 through our shim (bench/box2d): it builds, and its physics agrees with analytic answers.

The shim is built once from the Box2D v3 sources (tests/box2d_ref.py: --box2d-src, $STELKROPP_BOX2D_SRC
or ../shared/reference/box2d-v3) into the cache (STELKROPP_CACHE_DIR or
~/.cache/stelkropp) and reused by every test here; CI has gcc, cmake and ninja (.ci/run installs
them), so nothing is skipped. Bounds: analytic formulas, Box2D's own tolerances (B2_LINEAR_SLOP =
5 mm) and issue 14's 0.5 % pendulum bound.
"""
import json
import math
from pathlib import Path

import numpy as np
import pytest

from bench.box2d import build as B
from box2d_ref import box2d_v3
from bench.box2d.engine import Box2DV3Sim
from bench.suite import SUITE, measures
from bench.suite.common import body, box, capsule, circle, scene, segment
from bench.suite.ragdoll import standing_human
from bench.suite.samples import SAMPLES

ROOT = Path(__file__).resolve().parent.parent
G = 10.0
SLOP = 0.005  # B2_LINEAR_SLOP: Box2D's resting contacts keep up to this much overlap


@pytest.fixture(scope="module", autouse=True)
def built():
    return box2d_v3()  # skips, naming the way to provide the sources, only where there are none


def drop_scene(y0=10.0):
    return scene("fall", "", [body(box(0.5, 0.5), 0.0, y0, name="box")], gravity=(0.0, -G))


def test_build_reports_sources_and_reuses_cache(built):
    assert built.library.is_file() and built.benchmark.is_file()
    assert built.snapshot.startswith("617d32ab")  # ../shared/reference/box2d-v3/SNAPSHOT
    again = B.build()
    assert again.library == built.library  # same sources: the cached build, not a new one


def test_unavailable_without_sources_says_why(tmp_path):
    assert B.available(tmp_path) is False
    reason = B.why_unavailable(tmp_path)
    assert "no Box2D v3 sources" in reason and str(tmp_path) in reason


def test_free_fall_matches_symplectic_euler_per_substep():
    # Box2D integrates v += g h, then x += v h, each sub-step h = dt / 4: after n sub-steps
    # y = y0 - g h^2 n (n + 1) / 2 and v = -g h n (not 1/2 g t^2 exactly: that is its O(h) bias).
    sim = Box2DV3Sim(drop_scene(), substeps=4)
    steps = 60
    for _ in range(steps):
        sim.step()
    com, angle, v, w = sim.state()
    h, n = sim.dt / 4, 4 * steps
    assert com[0, 1] == pytest.approx(10.0 - G * h * h * n * (n + 1) / 2, abs=2e-5)
    assert v[0, 1] == pytest.approx(-G * h * n, rel=1e-5)
    assert abs(com[0, 1] - (10.0 - 0.5 * G * 1.0 ** 2)) < G * h * 1.0  # within one sub-step's bias of 1/2 g t^2


def test_resting_box_height():
    desc = scene("rest", "", [body(box(5.0, 0.5), 0.0, -0.5, kind="static"), body(box(0.5, 0.5), 0.0, 0.5)],
                 gravity=(0.0, -G))
    sim = Box2DV3Sim(desc)
    sim.run(120)
    com, angle, v, w = sim.state()
    assert 0.5 - SLOP <= com[1, 1] <= 0.5 + 1e-6
    assert abs(v[1, 1]) < 1e-3 and abs(angle[1]) < 1e-4


def test_pendulum_period_on_revolute_joint():
    # issue 14's bound: within 0.5 % of the pendulum formula (physical pendulum, finite amplitude)
    theta0 = 0.05
    sim = Box2DV3Sim(SAMPLES["rod_pendulum"](theta0=theta0))
    names = {k: v[0] for k, v in sim.names.items() if isinstance(k, str)}
    tr = measures.record(sim, 10.0, names)
    L, W, m = 1.0, 0.05, 0.05
    exact = measures.pendulum_period(theta0, m * (L * L + W * W) / 12 + m * (L / 2) ** 2, m * G * L / 2)
    assert exact == pytest.approx(2 * math.pi * math.sqrt(2 * L / (3 * G)), rel=2e-3)
    assert measures.period(tr, tr.angle[:, 0]) == pytest.approx(exact, rel=5e-3)
    assert float(np.abs(tr.joint_sep).max()) < SLOP  # the hinge holds


def test_version1_scene_file_builds_with_its_masses():
    desc = json.loads((ROOT / "scenes" / "pyramid.json").read_text())
    sim = Box2DV3Sim(desc)
    assert len(sim.masses) == len(desc["bodies"])
    dyn = sim.dynamic
    assert dyn.sum() == 210 and np.allclose(sim.masses[dyn], 1.0, rtol=1e-6)  # 1x1 boxes, density 1
    sim.run(30)
    com, _, _, _ = sim.state()
    assert np.isfinite(com).all()
    assert np.allclose(sim.origins()[dyn], com[dyn], atol=1e-6)  # boxes: origin = centre of mass


def test_version1_scene_with_springs_circles_and_polygons_builds():
    desc = json.loads((ROOT / "scenes" / "default.json").read_text())
    sim = Box2DV3Sim(desc)
    assert sim.counters()["joints"] == len(desc.get("springs", []))
    sim.run(60)
    assert np.isfinite(sim.state()[0]).all()


def test_version2_scene_with_shapes_and_joints_builds():
    desc = standing_human()
    sim = Box2DV3Sim(desc)
    assert sim.counters()["joints"] == 10
    hip = sim.slot("hip")
    r, hl = 0.095, 0.02
    assert sim.mass_data()[hip, 0] == pytest.approx(4 * r * hl + math.pi * r * r, rel=1e-5)  # capsule area x 1
    sim.run(60)
    sep = sim.joint_readouts()["linear_separation"]
    assert np.isfinite(sim.state()[0]).all() and np.abs(sep).max() < 0.02


def test_bad_fields_are_named():
    bad = scene("bad", "", [body([capsule((0, 0), (1, 0), -0.1)], name="a")])
    with pytest.raises(ValueError, match=r"bodies\[0\]\.shapes\[0\]\.capsule\.radius"):
        Box2DV3Sim(bad)
    bad = scene("bad", "", [body(box(0.5, 0.5), name="a")], joints=[{"kind": "revolute", "a": "a", "b": "nope",
                                                                       "anchor": [0, 0]}])
    with pytest.raises(ValueError, match=r"joints\[0\]\.b: no body named 'nope'"):
        Box2DV3Sim(bad)
    with pytest.raises(ValueError, match=r"bodies\[0\]: a dynamic body needs a shape with area"):
        Box2DV3Sim(scene("bad", "", [body(segment((0, 0), (1, 0)))]))


def test_friction_mixes_by_geometric_mean():
    # a box sliding at 3 m/s decelerates at sqrt(mu_box mu_ground) g: stops after v^2 / (2 mu g)
    mu_box, mu_ground, v0 = 0.9, 0.1, 3.0
    desc = scene("slide", "", [body(box(50.0, 0.5), 0.0, -0.5, kind="static", friction=mu_ground),
                               body(box(0.5, 0.5), 0.0, 0.5, velocity=(v0, 0.0), friction=mu_box, name="box")],
                 gravity=(0.0, -G))
    sim = Box2DV3Sim(desc)
    sim.run(300)
    mu = math.sqrt(mu_box * mu_ground)
    assert sim.origins()[1, 0] == pytest.approx(v0 * v0 / (2 * mu * G), rel=0.02)


def test_two_threads_match_one_thread_bit_for_bit():
    # Box2D v3 is deterministic across worker counts; our task system must not break that
    desc = SUITE["large_pyramid"](base=20)
    runs = []
    for threads in (1, 2):
        sim = Box2DV3Sim(desc, threads=threads, scheduler="shim")
        sim.run(60)
        runs.append(sim.snapshot())
    assert np.array_equal(runs[0], runs[1])


def test_events_add_and_remove_bodies_and_drives_move_kinematics():
    add = [body(circle(0.25), 0.0, 5.0, name="ball")]
    desc = scene("ev", "", [body(box(10.0, 0.5), 0.0, -0.5, kind="static", name="ground"),
                            body(box(0.5, 0.5), 0.0, 2.0, kind="kinematic", name="pusher")],
                 bench={"events": [{"step": 3, "add": {"bodies": add}}, {"step": 6, "remove": ["ball"]}],
                        "drives": [{"body": "pusher", "amplitude": [2.0, 0.0], "omega": 1.0}]})
    sim = Box2DV3Sim(desc)
    counts = []
    for _ in range(8):
        sim.step()
        counts.append(sim.counters()["bodies"])
    assert counts[1] == 3 and counts[3] == 4 and counts[-1] == 3  # shim ground + 2, + ball, - ball
    assert np.isnan(sim.state()[0][2]).all()
    # the pusher reaches the drive's target of the last step: x = 2 sin(7 dt)
    assert sim.origins()[1, 0] == pytest.approx(2.0 * math.sin(7 * sim.dt), abs=1e-5)


def test_chain_ground_is_smooth_and_one_sided():
    pts = [(10.0 - 0.5 * i, 0.0) for i in range(41)]  # right to left: solid below
    desc = scene("chain", "", [body({"chain": {"points": pts, "loop": False}}, kind="static"),
                               body(box(0.5, 0.5), -5.0, 0.5, velocity=(5.0, 0.0), friction=0.0, name="box")],
                 gravity=(0.0, -G))
    sim = Box2DV3Sim(desc)
    vmax = 0.0
    for _ in range(90):
        sim.step()
        vmax = max(vmax, abs(sim.state()[2][1, 1]))
    assert vmax < 0.01 and sim.origins()[1, 0] == pytest.approx(-5.0 + 5.0 * 1.5, rel=1e-3)


# bodies, shapes, joints that shared/benchmarks.c creates (dynamic + static bodies; a chain of n
# points in a loop is n segment shapes); rain: its static ground before the first ragdolls fall
BENCHMARKS_C = {"large_pyramid": (5051, 5051, 0), "many_pyramids": (22001, 22020, 0), "smash": (9601, 9601, 0),
                "joint_grid": (10000, 10000, 19800), "spinner": (6078, 6076 + 1 + 360, 1),
                "tumbler": (2026, 2029, 1), "washer": (8101, 8140, 0), "junkyard": (8002, 8262, 0),
                "compounds": (3001, 6282, 0), "rain": (1, 2505, 0)}


@pytest.mark.parametrize("name", sorted(SUITE))
def test_suite_scenes_build_what_benchmarks_c_builds(name):
    sim = Box2DV3Sim(SUITE[name](), sleeping=None)
    c = sim.counters()
    bodies, shapes, joints = BENCHMARKS_C[name]
    assert (c["bodies"] - 1, c["shapes"], c["joints"]) == (bodies, shapes, joints)  # - the shim's ground


def test_every_sample_builds_and_steps():
    for name, make in SAMPLES.items():
        sim = Box2DV3Sim(make())
        sim.run(2)
        assert np.isfinite(sim.state()[0]).all(), name
