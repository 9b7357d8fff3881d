"""The many-shape scenes in pymunk (bench/engines/pymunk_shapes.py): the benchmark's reference must
build the same bodies as ours, so every body's mass, centre of mass and moment of inertia in pymunk
must equal what Stelkropp computes for the same fixtures (both sum the parts with the parallel-axis
theorem; a lost fixture, a wrong offset or a wrong density shows at once)."""
import numpy as np
import pytest

pytest.importorskip("pymunk")

import physics  # noqa: E402
from bench.desc import load_desc, with_world  # noqa: E402
from bench.engines import build  # noqa: E402
from bench.paths import SCENES  # noqa: E402
from bench.scenes import SHAPE_BENCH  # noqa: E402


def both(name):
    desc = with_world(load_desc(SCENES / f"{name}.json"), sleeping=False)
    return build("pymunk", desc), physics.load_scene(SCENES / f"{name}.json")


@pytest.mark.parametrize("name", SHAPE_BENCH)
def test_pymunk_bodies_have_our_mass_properties(name):
    sim, world = both(name)
    assert len(sim.bodies) == len(world.bodies)
    nfix = sum(len(b.fixtures) for b in world.bodies)
    assert len(sim.space.shapes) == nfix  # one Chipmunk shape per fixture (chains: per segment)
    for pb, ours in zip(sim.bodies, world.bodies):
        if ours.kind != "dynamic":
            continue
        assert pb.mass == pytest.approx(ours.mass, rel=1e-9)
        assert pb.moment == pytest.approx(ours.inertia, rel=1e-6)
        com = pb.local_to_world(pb.center_of_gravity)
        assert np.allclose((com.x, com.y), ours.center_of_mass, atol=1e-9)


@pytest.mark.parametrize("name", SHAPE_BENCH)
def test_every_shape_scene_runs_in_pymunk(name):
    sim, _ = both(name)
    for _ in range(60):
        sim.step()
    com, ang, v, w = sim.state()
    assert np.isfinite(com).all() and np.isfinite(w).all()


def test_chain_segments_keep_their_neighbours_in_pymunk():
    # a ghost-less chain segment snags sliding bodies in Chipmunk too: the neighbours must be set
    sim, world = both("terrain")
    segs = [s for s in sim.space.shapes if type(s).__name__ == "Segment" and s.radius == 0.0]
    assert segs, "terrain has a chain"
    assert all(s.body.body_type == s.body.STATIC for s in segs)
