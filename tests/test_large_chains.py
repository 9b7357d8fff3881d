"""A 100,000-point chain (the most a scene file may hold) is added, saved and loaded whole: its
segments' vertices placed in one numpy pass, its fixtures compared on a fast path when saved and
its points checked in one loop against the schema.  How long that takes is measured by
``python -m bench.scene_limits`` (a benchmark, not a timed test)."""
import numpy as np

import physics


def test_a_100k_point_chain_adds_saves_and_loads(tmp_path):
    pts = np.c_[np.arange(100_000.0)[::-1], np.sin(np.arange(100_000.0))]
    world = physics.World()
    body = world.add_body(physics.Chain(pts), kind="static", name="ground")
    world.save_scene(tmp_path / "chain.json")
    again = physics.load_scene(tmp_path / "chain.json")
    chain = again.body("ground").fixtures[0].shape.chain
    assert np.array_equal(chain.points, pts) and len(again.body("ground").fixtures) == len(body.fixtures)
    F, G = world._store.fixtures.view, again._store.fixtures.view
    n = world._store.fixtures.n
    assert np.array_equal(F.ghost[:n], G.ghost[:n]) and np.array_equal(F.vstart[:n], G.vstart[:n])
    V, W = world._verts.view, again._verts.view
    assert np.array_equal(V.local[:2 * n], W.local[:2 * n]) and np.array_equal(V.normal[:2 * n], W.normal[:2 * n])
