"""The scenes in scenes/: each validates, round-trips, is what its generator makes, and runs
600 steps in every solver mode without non-finite values.  Also: the step models only what a
scene requires (the spring stage comes and goes with springs; sleeping scenes cost almost nothing).

The long runs -- the big scenes (rain: 1000 bodies, tumbler: 300, pyramid_large: 820) in every
mode, and the explicit penalty/hybrid modes on the stacks (each over 10 s here) -- are marked
``slow``: a plain ``pytest`` leaves them out, ``.ci/run`` runs them (``-m slow``), always the full
600 steps.
"""
import importlib.util
import math
import time
from pathlib import Path

import pytest

import physics
from physics.scene import load_scene, scene_metadata

from builders import finite
from end_states import digest, load_record
from test_scene import assert_same_world

ROOT = Path(__file__).resolve().parent.parent
SCENE_DIR = ROOT / "scenes"
SCENES = sorted(p.stem for p in SCENE_DIR.glob("*.json") if p.name != "stelkropp.schema.json")
BIG = {"rain", "tumbler", "pyramid_large"}
EXPECTED = {"pyramid", "pyramid_large", "card_house", "arch", "dominoes", "friction_ramp", "restitution_row",
            "spring_playground", "chain_bridge", "soft_body", "mass_ratio", "tumbler", "rain", "car", "default",
            "cup", "capsules", "terrain", "compounds",
            # issue 14's joint scenes (tests/test_joint_scenes.py: what they do)
            "pendulum", "double_pendulum", "newtons_cradle", "hinge_bridge", "ragdoll", "piston", "wrecking_ball",
            "walker", "joint_grid"}
STEPS = 600


def path(name):
    return SCENE_DIR / f"{name}.json"


# (scene, mode) runs of 600 steps measured over 10 s on this machine besides the big scenes
SLOW_RUNS = {("pyramid", "penalty"), ("pyramid", "hybrid"), ("default", "hybrid")}


def run_param(name, solver):
    slow = name in BIG or (name, solver) in SLOW_RUNS
    return pytest.param(name, solver, marks=[pytest.mark.slow] if slow else [], id=f"{name}-{solver}")


def test_every_promised_scene_is_shipped():
    assert EXPECTED <= set(SCENES)


@pytest.mark.parametrize("name", SCENES)
def test_scene_validates_and_describes_itself(name):
    w = load_scene(path(name))
    meta = scene_metadata(w)
    assert meta["name"] and len(meta["description"]) > 20
    assert w.dt == pytest.approx(1 / 60) and w.gravity == (0.0, -10.0)
    assert "camera" in meta


@pytest.mark.parametrize("name", SCENES)
def test_scene_round_trips(name, tmp_path):
    w1 = load_scene(path(name))
    out = tmp_path / f"{name}.json"
    w1.save_scene(out)
    assert_same_world(w1, load_scene(out))
    assert out.read_text() == path(name).read_text()  # shipped files are in saved (canonical) form


def test_generator_makes_the_committed_files():
    spec = importlib.util.spec_from_file_location("make_scenes", SCENE_DIR / "make_scenes.py")
    gen = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(gen)
    assert set(gen.SCENES) == set(SCENES)
    for name, make in gen.SCENES.items():
        assert gen.canonical(make()) == path(name).read_text(), f"regenerate: scenes/make_scenes.py {name}"


# -- what the scenes contain ----------------------------------------------------
def dynamic(w):
    return [b for b in w.bodies if b.kind == "dynamic"]


def test_pyramid_contents():
    w = load_scene(path("pyramid"))
    ground = w.body("ground")
    assert ground.kind == "static" and ground.shape.spec == {"box": [40.0, 1.0]} and ground.position == (0, -0.5)
    boxes = dynamic(w)
    assert len(boxes) == 210
    assert all(b.shape.spec == {"box": [1.0, 1.0]} and b.friction == (0.6, 0.6) for b in boxes)
    assert len(dynamic(load_scene(path("pyramid_large")))) == 820


def test_restitution_row_contents():
    w = load_scene(path("restitution_row"))
    assert sorted(b.restitution for b in dynamic(w)) == [0.0, 0.25, 0.5, 0.75, 1.0]


def test_friction_ramp_has_three_boxes_with_three_frictions():
    w = load_scene(path("friction_ramp"))
    assert len({b.friction for b in dynamic(w)}) == 3 == len(dynamic(w))


def test_mass_ratio_has_100_kg_on_1_kg():
    w = load_scene(path("mass_ratio"))
    assert w.body("heavy_top").mass == pytest.approx(100) and w.body("light_bottom").mass == pytest.approx(1)


def test_arch_is_made_of_general_convex_polygons():
    w = load_scene(path("arch"))
    stones = [b for b in w.bodies if b.name.startswith("voussoir")]
    assert len(stones) >= 7 and all("polygon" in b.shape.spec for b in stones)


def test_big_scenes_have_their_body_counts():
    assert len(dynamic(load_scene(path("rain")))) == 1000
    tumbler = load_scene(path("tumbler"))
    assert len(dynamic(tumbler)) == 300
    # the drum: one kinematic body of four box fixtures, turning
    assert any(b.kind == "kinematic" and b.angular_velocity != 0 and len(b.fixtures) == 4 for b in tumbler.bodies)
    compounds = dynamic(load_scene(path("compounds")))
    assert len(compounds) == 30 and all(len(b.fixtures) >= 2 for b in compounds)


def test_spring_scenes_have_springs():
    for name in ("spring_playground", "chain_bridge", "soft_body"):
        assert load_scene(path(name)).springs, name


def test_car_runs_on_wheel_joints_with_a_motor():
    # issue 14: the default car has two wheel joints and a motor (the spring axles are gone)
    w = load_scene(path("car"))
    wheels = [j for j in w.joints if j.kind == "wheel"]
    assert len(wheels) == 2 and not w.springs
    assert sum(j.max_motor_torque > 0 and j.motor_speed != 0 for j in wheels) == 1
    assert all(j.spring_hertz > 0 for j in wheels)


def test_default_scene_is_inviting():
    w = load_scene(path("default"))
    assert 100 <= len(w.bodies) <= 300
    kinds = {next(iter(b.shape.spec)) for b in w.bodies}
    assert {"box", "circle", "regular", "polygon"} <= kinds and w.springs
    assert set(scene_metadata(w)["camera"]) == {"center", "zoom"}


# -- every scene in every solver mode -------------------------------------------------
@pytest.mark.parametrize("name,solver", [run_param(n, s) for n in SCENES for s in physics.solvers_available()])
def test_scene_runs_600_steps_in_every_mode(name, solver):
    w = load_scene(path(name))
    w.solver = solver
    for _ in range(STEPS):
        w.step()  # raises SimulationError on a non-finite value
    assert w.steps == STEPS
    assert finite(w)
    # behaviour unchanged: the end state is the recorded one, bit for bit (tests/end_states.py)
    assert digest(w) == load_record()[f"{name}/{solver}"], \
        f"{name}/{solver}: the 600-step end state changed; if deliberate, re-record (python -m tests.end_states)"


# -- model only what a scene requires ---------------------------------------------
def spring_stages(w):
    return [s for s in w.info()["stages"] if "spring" in s]


@pytest.mark.parametrize("solver", physics.solvers_available())
def test_spring_stage_follows_the_springs(solver):
    w = load_scene(path("mass_ratio"))  # no springs
    w.solver = solver
    assert spring_stages(w) == []
    sp = w.add_spring(w.body("tower2"), None, anchor_b=(6, 6), stiffness=10)
    assert spring_stages(w), f"{solver}: no spring stage with a spring: {w.info()['stages']}"
    w.step()
    w.remove(sp)
    assert spring_stages(w) == [], f"{solver}: spring stage without springs: {w.info()['stages']}"
    w.step()


def test_sleeping_scene_steps_at_least_20x_faster():
    w = load_scene(path("pyramid"))
    for _ in range(1200):
        w.step()
        if w.info()["awake"] == 0:
            break
    assert w.info()["awake"] == 0, "the pyramid should fall asleep"
    n = 300

    def per_step():
        t = time.perf_counter()
        for _ in range(n):
            w.step()
        return (time.perf_counter() - t) / n

    asleep = min(per_step() for _ in range(3))
    assert w.info()["awake"] == 0
    w.sleeping = False  # the same scene, every body awake (and kept awake)
    w.step()
    awake = min(per_step() for _ in range(3))
    assert awake >= 20 * asleep, f"asleep {asleep * 1e6:.1f} us/step, awake {awake * 1e6:.1f} us/step"
    assert math.isfinite(awake)
