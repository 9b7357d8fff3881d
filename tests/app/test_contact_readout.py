"""Issue 15, the stats window's contact readout: the selected body's contacts with their normal
and tangent impulses per manifold point, and its contact hits per second (app-side begin
detection until the core's events land: app/contact_events.py).  Checked against analytic
figures: a box resting on the ground carries its weight, so its contact's normal impulses over
one step sum to m g dt; a ball dropped from rest first touches the ground after sqrt(2 h / g).
The ball does not bounce (restitution 0): a fast bounce is over before any step starts with the
pair touching, so ``world.contacts()`` never lists it and the app-side detection cannot see it
(docs/sandbox.md, "Contact readout"; the core's events will)."""
from __future__ import annotations

import json
import math

import pytest

from test_tools import body, to_screen

pytestmark = pytest.mark.app

G = 10.0
DROP = 1.75          # m from the ball's bottom to the ground


def scene(path):
    """Sleeping off: a sleeping body's contacts are not in ``world.contacts()``."""
    data = {"format": "stelkropp.scene", "version": 2, "name": "contacts",
            "world": {"gravity": [0, -G], "sleeping": False}, "camera": {"center": [0.0, 2.0], "zoom": 40.0},
            "bodies": [
                {"name": "ground", "kind": "static", "shape": {"box": [16, 1]}, "position": [0, -0.5]},
                {"name": "rest", "shape": {"box": [1, 1]}, "position": [-3, 0.5], "density": 2.0},
                {"name": "ball", "shape": {"circle": 0.25}, "position": [3, DROP + 0.25], "restitution": 0.0}]}
    path.write_text(json.dumps(data))
    return path


def readout(s):
    return s["ui_values"].get("contacts") or {}


def test_contact_impulses_and_hits_per_second(launch, tmp_path):
    app = launch(scene(tmp_path / "contacts.json"), "--paused")
    st = app.wait_ready(10)
    ball = body(st, "ball")
    app.click(*to_screen(st, ball["position"]))
    st = app.wait(lambda s: readout(s).get("body") == ball["id"], 10, "the ball selected")
    assert readout(st)["contacts"] == [] and readout(st)["hit_times"] == []
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    st = app.wait(lambda s: s["time"] > 1.0, 60, "the first bounce")
    app.key("space")
    st = app.wait(lambda s: not s["running"], 10, "paused")
    st = app.settle()
    hits = readout(st)["hit_times"]
    t_hit = math.sqrt(2 * DROP / G)
    # the core's hit event of the landing step (world.contact_events().hit, read after every
    # step), stamped with the time at the step's end: within a step or two of the analytic fall
    assert len(hits) == 1 and t_hit - 0.01 <= hits[0] <= t_hit + 2 * st["dt"], (hits, t_hit)
    window = [t for t in hits if t > st["time"] - 1.0]
    assert readout(st)["hits_per_second"] == pytest.approx(len(window)), readout(st)
    # the resting box: one contact with the ground, its normal impulses summing to m g dt
    rest = body(st, "rest")
    app.click(*to_screen(st, rest["position"]))
    st = app.wait(lambda s: readout(s).get("body") == rest["id"] and readout(s)["contacts"], 10, "the box selected")
    st = app.settle()
    (c,) = readout(st)["contacts"]
    assert c["other"] == body(st, "ground")["id"] and len(c["normal_impulses"]) == 2
    weight_impulse = rest["mass"] * G * st["dt"]
    assert sum(c["normal_impulses"]) == pytest.approx(weight_impulse, rel=0.03), (c, weight_impulse)
    assert all(abs(t) < 0.02 * weight_impulse for t in c["tangent_impulses"]), c   # nothing pushes sideways
    assert readout(st)["picked"] == c["pair"] and "stats:contacts" in st["ui_rects"]
    app.screenshot("contact_readout")
    assert not st["gl_errors"]
