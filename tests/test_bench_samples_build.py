"""Every Box2D v3 sample description (bench/suite/samples.py) and every suite scene with several
shapes per body builds in Stelkropp, with its real shapes, materials and joints, and steps with
finite state (issue 18: the sample harness ran stand-in polygons and no joints before).

Two builders must agree: ``build_ours_world`` (a description's records, the benchmark's path)
and ``scene_world`` (the scene loader, the path ``bench.reliability --samples`` runs); their
masses, centres of mass and fixture materials are compared body by body.
"""
import numpy as np
import pytest

from bench.engines.ours import OursSim, build_ours_world, scene_world
from bench.suite import benchmarks as SB
from bench.suite.ragdoll import rain
from bench.suite.samples import SAMPLES

# the suite scenes that have bodies of several shapes, at sizes a test can step
SMALL_SUITE = {"many_pyramids": lambda: SB.many_pyramids(rows=2, columns=2, base=3),
               "tumbler": lambda: SB.tumbler(grid=3), "washer": lambda: SB.washer(grid=3),
               "junkyard": lambda: SB.junkyard(columns=3, rows=2), "compounds": lambda: SB.compounds(columns=2, rows=3),
               "spinner": lambda: SB.spinner(count=20), "rain": rain}
SCENES = {**SAMPLES, **SMALL_SUITE}


def _finite_after(desc, world, steps=10):
    sim = OursSim(desc, world=world, solver="soft_step")
    for _ in range(steps):
        sim.step()
    com, ang, v, w = sim.state()
    return all(np.isfinite(a).all() for a in (com, ang, v, w)), sim


def _has_several_shapes(desc):
    return any(len(b.get("shapes", [])) > 1 for b in desc["bodies"])


def test_the_suite_list_covers_every_scene_with_compounds():
    """A bench suite scene with several shapes per body is in SMALL_SUITE (checked at full size)."""
    from bench.suite import SUITE
    assert {n for n, make in SUITE.items() if n != "rain" and _has_several_shapes(make())} <= set(SMALL_SUITE)
    assert _has_several_shapes(SAMPLES["vertical_stack"]()) and _has_several_shapes(SAMPLES["cliff"]())


@pytest.mark.parametrize("name", sorted(SCENES))
def test_builds_from_records_and_steps_finite(name):
    desc = SCENES[name]()
    world = build_ours_world(desc)
    assert len(world.bodies) == len(desc["bodies"])
    assert len(world.joints) == len(desc.get("joints", []))
    ok, _ = _finite_after(desc, world)
    assert ok, name


@pytest.mark.parametrize("name", sorted(SCENES))
def test_loader_builds_the_same_bodies_and_steps_finite(name):
    desc = SCENES[name]()
    loaded, records = scene_world(desc), build_ours_world(desc)
    for i, (a, b) in enumerate(zip(loaded.bodies, records.bodies)):
        assert np.isclose(a.mass, b.mass, rtol=1e-12, atol=0.0), (name, i)
        assert np.allclose(a.position, b.position, rtol=0.0, atol=1e-12), (name, i)
        assert [(f.density, f.friction, f.restitution) for f in a.fixtures] == \
               [(f.density, f.friction, f.restitution) for f in b.fixtures], (name, i)
    ok, _ = _finite_after(desc, loaded)
    assert ok, name


def test_several_fixtures_keep_their_own_materials():
    """vertical_stack's ground is two segments on one static body; cliff's ramps mix polygons and a
    segment; a capsule's friction is its shape's (0.01 in cliff), not the body's."""
    world = build_ours_world(SAMPLES["vertical_stack"]())
    assert [type(f.shape).__name__ for f in world.bodies[0].fixtures] == ["Segment", "Segment"]
    cliff = SAMPLES["cliff"]()
    frictions = {f.friction for b in build_ours_world(cliff).bodies for f in b.fixtures}
    assert (0.01, 0.01) in frictions and (0.6, 0.6) in frictions


def test_joint_readouts_have_box2d_layout_and_hold_the_prismatic_column():
    """multiple_prismatic: six prismatic joints; after 10 steps every joint separation is below a
    millimetre (Box2D v3 holds 0.7 mm at 10 s: multiple_prismatic.max_joint_separation_10s in
    bench/results/box2d_v3_figures.json) and every readout is finite."""
    desc = SAMPLES["multiple_prismatic"]()
    ok, sim = _finite_after(desc, scene_world(desc))
    r = sim.joint_readouts()
    assert ok and r["force"].shape == (6, 2) and r["valid"].all()
    assert all(np.isfinite(r[k]).all() for k in ("force", "torque", "linear_separation", "value", "rate"))
    assert r["linear_separation"].max() < 1e-3


def test_revolute_readouts_match_the_definitions():
    """hanging_body: a 1 kg box hanging at rest from a world hinge at its top edge; the reaction on
    the box holds its weight (m g up, 10 N with the cases' g) and the anchors coincide."""
    desc = SAMPLES["hanging_body"]()
    ok, sim = _finite_after(desc, scene_world(desc), steps=30)
    r = sim.joint_readouts()
    g = -desc["world"]["gravity"][1]
    assert ok and abs(r["force"][0, 1] - sim.masses[0] * g) < 1e-6 * g and abs(r["force"][0, 0]) < 1e-9
    assert r["linear_separation"][0] < 1e-9 and r["value"][0] == pytest.approx(0.0, abs=1e-9)
