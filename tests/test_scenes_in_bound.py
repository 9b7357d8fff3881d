"""No shipped scene loses bodies to the sandbox's world bound in 10 s of play: opened as the
sandbox opens it (the bound fitted to the scene, app/bound.py) and run 600 steps in its own solver
mode, no moving body's centre crosses the bound.  soft_body once threw 15 bodies out this way
(the window test tests/app/test_bound_removals.py plays it for 20 s in the sandbox itself).

The big scenes (rain, tumbler, pyramid_large) are marked ``slow``."""
from __future__ import annotations

from pathlib import Path

import pytest

import physics
from app.bound import WorldBound

ROOT = Path(__file__).resolve().parent.parent
SCENES = sorted(p.stem for p in (ROOT / "scenes").glob("*.json") if p.name != "stelkropp.schema.json")
BIG = {"rain", "tumbler", "pyramid_large"}
CHECK_EVERY = 5       # steps between checks: nothing in these scenes crosses a 10 m margin and back in 5


def lost_bodies(world, steps=600):
    """The names of the moving bodies whose centre left the fitted bound within ``steps`` steps."""
    bound = WorldBound()
    bound.fit_scene(world.render_data())
    names = {b.id: b.name or f"body {b.id}" for b in world.bodies}
    lost = []
    for k in range(1, steps + 1):
        world.step()
        if k % CHECK_EVERY == 0:
            lost += [names[int(i)] for i in bound.crossed(world.render_data())]
    return lost


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.slow) if n in BIG else n for n in SCENES])
def test_shipped_scene_keeps_its_bodies_for_10_seconds(name):
    world = physics.load_scene(ROOT / "scenes" / f"{name}.json")
    assert lost_bodies(world) == []


def test_a_body_thrown_out_is_seen_leaving():
    # the check can fail: a box thrown sideways at 40 m/s leaves a 16 m floor's bound within 10 s
    w = physics.World(gravity=(0, -10))
    w.add_body(physics.Polygon.box(16, 1), kind="static", position=(0, -0.5))
    w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5), velocity=(40.0, 0.0), name="thrown")
    assert lost_bodies(w) == ["thrown"]
