"""The joint tool makes any kind the core declares (physics/joint_params.py), driven as a person
would: real X events under Xvfb, the kind chosen by its button in the Tools panel.

A rotary joint made by a click on a body in the air, given a motor in the inspector, turns the
body at the motor's speed while the body falls freely (the joint holds the angle and no point:
its centre falls as g t^2 / 2); a distance joint is dragged from a body to a point above it; a
motor joint clicked on the bar holds it where it is."""
from __future__ import annotations

import json

import pytest
from sandbox_pixels import pink_pixels
from test_joint_tools import W, ids, new_joint, pick_tool, to_screen

import physics

pytestmark = pytest.mark.app


def scene(path):
    data = {
        "format": "stelkropp.scene", "version": 1, "name": "any joint",
        "camera": {"center": [0.0, 2.0], "zoom": 40.0},
        "bodies": [
            {"name": "ground", "kind": "static", "shape": {"box": [24, 1]}, "position": [0, -8.5]},
            {"name": "r", "shape": {"box": [1.6, 0.4]}, "position": [-4.0, 4.0]},
            {"name": "d", "shape": {"box": [0.8, 0.8]}, "position": [4.0, 3.0]},
        ],
    }
    path.write_text(json.dumps(data))
    return path


def choose_kind(app, kind):
    st = app.wait(lambda s: f"tools:joint_kind:{kind}" in s["ui_rects"], 10, f"the {kind} button")
    x0, y0, x1, y1 = st["ui_rects"][f"tools:joint_kind:{kind}"]
    app.click(x0 + 8, (y0 + y1) / 2)
    app.frames(3)


def type_into(app, field, keys):
    st = app.wait(lambda s: f"inspector:joint:{field}" in s["ui_rects"], 10, f"the {field} field")
    x0, y0, x1, y1 = st["ui_rects"][f"inspector:joint:{field}"]
    app.click(x0 + 40, (y0 + y1) / 2)
    app.frames(3)
    app.key("ctrl+a", "BackSpace", *keys, "Return")


def test_the_joint_tool_makes_a_rotary_and_a_distance_joint(launch, tmp_path):
    app = launch(scene(tmp_path / "any.json"), "--paused")
    st0 = app.wait_ready(20)
    names = ids(st0)
    pick_tool(app, "joint")
    choose_kind(app, "rotary")
    press = (-4.3, 4.0)
    x, y = to_screen(st0, press)
    before = pink_pixels(app.screenshot("no_joint"), x - 8, y - 8, x + 8, y + 8)
    app.click(x, y)
    st, j = new_joint(app, 1, "the rotary joint")
    assert (j["kind"], j["a"], j["b"]) == ("rotary", names["r"], None), j
    assert st["selected_joints"] == [j["id"]]
    assert j["anchor_a"] == pytest.approx(press, abs=0.05)
    # the inspector edits the declared parameters: a motor of 3 rad/s
    type_into(app, "max_motor_torque", ["5", "0"])
    app.wait(lambda s: s["joints"][0]["params"]["max_motor_torque"] == 50.0, 10, "the motor torque")
    type_into(app, "motor_speed", ["3"])
    app.wait(lambda s: s["joints"][0]["params"]["motor_speed"] == 3.0, 10, "the motor speed")
    app.key("Escape")
    st = app.frames(4)
    drawn = pink_pixels(app.screenshot("rotary"), x - 8, y - 8, x + 8, y + 8)
    assert drawn > before + 20, f"the rotary joint is not drawn ({drawn} vs {before})"
    # run: the body turns at the motor's speed while its centre falls freely
    app.xdo("mousemove", *map(int, to_screen(st0, (0.0, 7.0))))
    app.settle()
    app.key("space")
    st = app.wait(lambda s: s["running"] and s["time"] > 0.5, 30, "half a second of running")
    app.key("space")
    st = app.wait(lambda s: not s["running"], 10, "paused again")
    body = next(b for b in st["bodies"] if b["id"] == names["r"])
    t = st["time"]
    g = -physics.load_scene(tmp_path / "any.json").gravity[1]
    assert body["angular_velocity"] == pytest.approx(3.0, rel=0.01)
    assert body["position"][1] == pytest.approx(4.0 - 0.5 * g * t * t, abs=0.02)   # free fall, no point held
    assert body["position"][0] == pytest.approx(-4.0, abs=1e-6)
    # a distance joint: dragged from the other body to a point above it (the background)
    pick_tool(app, "joint")
    choose_kind(app, "distance")
    p0 = next(b for b in st["bodies"] if b["id"] == names["d"])["position"]   # it fell while the scene ran
    p1 = (p0[0], p0[1] + 3.0)
    app.drag(to_screen(st0, p0), to_screen(st0, p1), steps=12)
    app.xdo("mouseup", 1)
    st, j = new_joint(app, 2, "the distance joint")
    assert (j["kind"], j["a"], j["b"]) == ("distance", names["d"], None), j
    assert j["anchor_b"] == pytest.approx(p1, abs=0.05)
    assert j["params"]["length"] == pytest.approx(3.0, abs=0.05)
    # a motor joint to the world, clicked on the rotary's bar: it holds the bar where it is (its
    # targets are the bar's pose now, not the world origin), so the bar stops falling
    choose_kind(app, "motor")
    bar = next(b for b in st["bodies"] if b["id"] == names["r"])
    app.click(*to_screen(st0, bar["position"]))
    st, j = new_joint(app, 3, "the motor joint")
    assert (j["kind"], j["a"], j["b"]) == ("motor", names["r"], None), j
    assert j["params"]["linear_offset"] == pytest.approx(bar["position"], abs=1e-6)
    app.xdo("mousemove", *map(int, to_screen(st0, (0.0, 7.0))))
    app.settle()
    app.key("space")
    t0 = st["time"]
    st = app.wait(lambda s: s["time"] > t0 + 1.0, 30, "a second more")
    held = next(b for b in st["bodies"] if b["id"] == names["r"])["position"]
    # 100 N against the bar's 6 N weight pulls it back from where it fell meanwhile (< 0.2 m)
    assert held == pytest.approx(bar["position"], abs=0.2), (held, bar["position"])
    assert st["ui_rects"]["tool:joint"][2] <= W and not st["gl_errors"] and not st["fault"]
