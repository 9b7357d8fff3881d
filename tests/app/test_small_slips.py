"""Smaller slips: an unnamed body saved for a spring is named by the id the sandbox showed;
pasted copies keep their names ("q copy"); a body pinned to the world and moved with the move
handle takes its pin along (it stays where it was put when the scene plays)."""
from __future__ import annotations

import json

import pytest

from sandbox_pixels import body_pixels
from test_joint_tools import pick_tool
from test_saving import scene_point
from test_tools import to_screen

pytestmark = pytest.mark.app


def slips_scene(path):
    data = {"format": "stelkropp.scene", "version": 2, "name": "slips",
            "camera": {"center": [0.0, 2.0], "zoom": 40.0},
            "bodies": [
                {"name": "ground", "kind": "static", "shape": {"box": [16, 1]}, "position": [0, -0.5]},
                {"name": "w", "kind": "static", "shape": {"box": [0.4, 0.4]}, "position": [6, 1]},
                {"shape": {"box": [0.5, 0.5]}, "position": [6, 3]},          # unnamed
                {"name": "p", "shape": {"box": [1.0, 0.4]}, "position": [-4, 4]},
                {"name": "q", "shape": {"box": [0.6, 0.6]}, "position": [-2, 0.3]},
            ],
            "joints": [{"kind": "revolute", "name": "pin", "a": "p", "b": None, "anchor": [-4.4, 4]}]}
    path.write_text(json.dumps(data))
    return path


def by_name(st, name):
    return next(b for b in st["bodies"] if b["name"] == name)


def test_saved_names_pasted_names_and_moved_pins(launch, tmp_path):
    path = slips_scene(tmp_path / "slips.json")
    app = launch(path, "--paused")
    st = app.wait_ready(10)
    # -- a spring from the unnamed body to w: saved, the body is named by its id
    unnamed = next(b for b in st["bodies"] if b["name"] is None)
    pick_tool(app, "spring")
    app.drag(unnamed["screen"], to_screen(st, (6.0, 1.0)), steps=8)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: s["n_springs"] == 1, 10, "the spring")
    app.xdo("mousemove", *scene_point(st))
    app.settle()
    app.key("ctrl+s")
    app.wait(lambda s: not s["dirty"], 15, "the save")
    saved = [b.get("name") for b in json.loads(path.read_text())["bodies"]]
    assert f"body{unnamed['id']}" in saved, (unnamed["id"], saved)
    # -- pasted copies keep their names
    pick_tool(app, "select")
    st = app.settle()
    p, q = by_name(st, "p"), by_name(st, "q")
    app.click(*q["screen"])
    app.wait(lambda s: s["selection"] == [q["id"]], 10, "q selected")
    app.key("ctrl+c")
    n = st["n_bodies"]
    for k, x in enumerate((1.0, 3.0)):
        app.xdo("mousemove", *map(int, to_screen(st, (x, 3.0))))
        app.settle()
        app.key("ctrl+v")
        st = app.wait(lambda s, k=k: s["n_bodies"] == n + k + 1, 10, "a paste")
    names = sorted(b["name"] for b in st["bodies"] if b["name"] and b["name"].startswith("q"))
    assert names == ["q", "q copy", "q copy 2"], names
    # -- p (pinned to the world) and q moved 3 m right with the move handle: the pin comes along
    app.click(*p["screen"])
    app.xdo("keydown", "shift")
    app.click(*q["screen"])
    app.xdo("keyup", "shift")
    st = app.wait(lambda s: sorted(s["selection"]) == sorted([p["id"], q["id"]]), 10, "p and q selected")
    centre = ((-4.5 - 1.7) / 2, (0.0 + 4.2) / 2)      # the selection box's: p's top-left to q's bottom-right
    app.drag(to_screen(st, centre), to_screen(st, (centre[0] + 3.0, centre[1])), steps=10)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: next(j for j in s["joints"] if j["name"] == "pin")["anchor_b"][0] > -2.0, 10,
                  "the pin moved with p")
    pin = next(j for j in st["joints"] if j["name"] == "pin")
    assert pin["anchor_b"] == pytest.approx([-1.4, 4.0], abs=0.1), pin
    app.xdo("mousemove", *scene_point(st))
    app.settle()
    app.key("Escape")                    # deselected: drawn in its own colour
    app.key("space")
    st = app.wait(lambda s: s["time"] > 1.0, 30, "1 s of play")
    pos = by_name(st, "p")["position"]
    assert abs(pos[0] - (-1.0)) < 0.8, f"p went back to its old pin: {pos}"
    img = app.screenshot("moved_pin")
    x, y = map(int, to_screen(st, pos))
    assert body_pixels(img, x - 4, x + 4, y - 4, y + 4, static=False) > 20, "p is not drawn where it swings"
