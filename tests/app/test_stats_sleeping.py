"""The stats window's counts in a world where some bodies sleep: the core tests no pair of two
sleeping bodies, so a pile of sleeping boxes has no contacts in ``world.contacts()`` nor in
``world.info()['contacts']``.  The counts line must say its contacts are the awake ones, show how
many bodies sleep, and read the same figures the public API gives for the same step (a world
loaded from the same file and stepped as often in this process), on a line the window does
not clip."""
from __future__ import annotations

import json

import numpy as np
import pytest

import physics

pytestmark = pytest.mark.app

STACK = [(-22.0 + i, 0.5 + j) for i in range(3) for j in range(3)]   # nine boxes, asleep from the start
BALLS = {"ball1": 4.0, "ball2": 10.0}                                   # rolling right: awake on the ground


def scene(path):
    """A sleeping 3x3 stack of boxes and two balls rolling without slip (no rolling resistance
    in the core, so they stay awake) away from it on a long ground."""
    boxes = [{"name": f"box{k}", "shape": {"box": [1, 1]}, "position": list(p), "asleep": 0}
             for k, p in enumerate(STACK)]
    balls = [{"name": n, "shape": {"circle": 0.5}, "position": [x, 0.5], "velocity": [1.0, 0.0],
              "angular_velocity": -2.0} for n, x in BALLS.items()]
    data = {"format": "stelkropp.scene", "version": 2, "name": "sleeping stack",
            "world": {"gravity": [0, -10], "sleeping": True}, "camera": {"center": [-4.0, 2.0], "zoom": 24.0},
            "bodies": [{"name": "ground", "kind": "static", "shape": {"box": [60, 1]}, "position": [0, -0.5]},
                       *boxes, *balls]}
    path.write_text(json.dumps(data))
    return path


def counts(s):
    return s["ui_values"].get("stats:counts") or {}


def replayed(path, steps):
    """The same scene loaded here and stepped ``steps`` times: the public API's view of that step."""
    world = physics.load_scene(str(path))
    for _ in range(steps):
        world.step()
    return world


def test_counts_say_awake_and_match_the_api(launch, tmp_path):
    path = scene(tmp_path / "sleeping.json")
    app = launch(path, "--paused")      # played here for a second: the balls stay on the ground
    app.wait_ready(10, joints=False)
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    app.wait(lambda s: s["running"] and s["time"] > 1.0, 60, "a second of play")
    app.key("space")
    app.wait(lambda s: not s["running"], 10, "paused")
    # the counts are read every sixth frame: wait for a read of the paused step
    st = app.wait(lambda s: counts(s).get("steps") == s["steps"], 10, "the counts of the paused step")
    c = counts(st)
    awake = {b["name"] for b in st["bodies"] if b["awake"] and b["kind"] == "dynamic"}
    assert awake == set(BALLS), f"the scene is not mixed as meant: awake {awake}"
    # (a) the line says what it counts
    assert "awake contacts" in c["text"] and "asleep 9" in c["text"], c["text"]
    assert f"awake contacts: {c['touching']} touching, {c['pairs']} pairs tested" in c["text"], c["text"]
    assert (c["awake"], c["asleep"], c["touching"]) == (2, 9, 2), c   # each ball on the ground
    # (b) the public API at the same step
    world = replayed(path, st["steps"])
    for b in world.bodies:
        if b.name in BALLS:
            shown = next(x for x in st["bodies"] if x["name"] == b.name)
            assert np.allclose(b.position, shown["position"], atol=1e-9), (b.name, b.position, shown)
    info = world.info()
    assert c["touching"] == len(world.contacts()) == len(world.contact_depths())
    assert c["pairs"] == info["contacts"]
    assert (c["awake"], c["asleep"]) == (info["awake"], info["dynamic"] - info["awake"])
    assert c["bodies"] == info["bodies"] == len(STACK) + len(BALLS) + 1
    # (c) on the screen: inside the stats window, drawn to its end
    x0, y0, x1, y1 = st["ui_rects"]["stats:counts"]
    wx0, wy0, wx1, wy1 = st["ui_rects"]["stats_window"]
    assert wx0 < x0 and x1 <= wx1 - 6 and wy0 < y0 and y1 < wy1, ("the counts line is clipped", (x0, x1), (wx0, wx1))
    img = app.screenshot("stats_sleeping")
    line = img[int(y0):int(y1) + 1, int(x0):int(x1) + 1]
    lit = np.flatnonzero((line.min(axis=2) > 120).any(axis=0))
    assert len(lit) and lit[0] < 6 and lit[-1] > line.shape[1] - 8, f"the line is not drawn end to end: {lit[:3]} {lit[-3:]}"
    assert not st["gl_errors"]
