"""The joint tools (issue 14, "The sandbox") driven as a person would: real X events (xdotool).

Each tool makes its joint over the bodies under the pointer; the joints are drawn (pink pixels
where they are), selectable, undone and redone, duplicated with their bodies and saved; a motor's
speed edited in the inspector turns its body at the new speed while the scene runs.
"""
from __future__ import annotations

import json

import numpy as np
import pytest

from sandbox_pixels import pink_pixels

pytestmark = pytest.mark.app

W, H = 1280, 800


def joints_scene(path):
    """One body (or pair) per joint tool, in the air, the scene paused so they stay put."""
    def box(name, w, h, x, y):
        return {"name": name, "shape": {"box": [w, h]}, "position": [x, y]}
    data = {
        "format": "stelkropp.scene", "version": 1, "name": "joint tools",
        "camera": {"center": [0.0, 2.0], "zoom": 40.0},
        "bodies": [
            {"name": "ground", "kind": "static", "shape": {"box": [24, 1]}, "position": [0, -0.5]},
            box("h", 1.0, 1.0, -8.0, 4.0),                                 # hinge: pinned to the background
            box("m", 1.2, 0.4, -5.0, 4.0),                                 # motor: pinned at its centre
            box("f1", 1.0, 1.0, -2.0, 4.0), box("f2", 1.0, 1.0, -1.4, 4.4),  # fixate: f2 welded onto f1
            box("s", 1.0, 1.0, 1.5, 4.0),                                  # slider: dragged up 2.5 m
            box("r", 0.8, 0.8, 4.5, 3.0),                                  # rope: to the background above
            box("chassis", 2.0, 0.5, 8.0, 4.0),
            {"name": "wh", "shape": {"circle": 0.35}, "position": [8.7, 3.9]},   # wheel: over the chassis
        ],
    }
    path.write_text(json.dumps(data))
    return path


def to_screen(st, p):
    c, s = st["camera"]["center"], st["camera"]["scale"]
    return (W / 2 + (p[0] - c[0]) * s, H / 2 - (p[1] - c[1]) * s)


def ids(st):
    return {b["name"]: b["id"] for b in st["bodies"]}


def pick_tool(app, name):
    """Click the tool's button in the Tools panel (the keys reach only the first nine tools)."""
    st = app.status()
    x0, y0, x1, y1 = st["ui_rects"][f"tool:{name}"]
    app.click((x0 + x1) / 2, (y0 + y1) / 2)
    return app.wait(lambda s: s["tool"] == name, 10, f"the {name} tool")


def new_joint(app, n, what):
    st = app.wait(lambda s: s["n_joints"] == n, 15, what)
    return st, max(st["joints"], key=lambda j: j["id"])


#: per tool: how it is used (click at a point, or drag from a point to a point), the joint it must
#: make (kind, body a, body b) and a screen box (world centre, half width and height px) where it
#: is drawn: the pin, the weld mark, the axis above the slider, the rope, the wheel's hub and coil
CASES = (
    ("hinge", ("click", (-8.0, 4.3)), ("revolute", "h", None), ((-8.0, 4.3), 9, 9)),
    ("motor", ("click", (-5.0, 4.0)), ("revolute", "m", None), ((-5.0, 4.0), 9, 9)),
    ("fixate", ("click", (-1.7, 4.2)), ("weld", "f2", "f1"), ((-1.7, 4.2), 9, 9)),
    ("slider", ("drag", (1.5, 4.0), (1.5, 6.5)), ("prismatic", "s", None), ((1.5, 5.6), 8, 20)),
    ("rope", ("drag", (4.5, 3.0), (4.5, 6.5)), ("distance", "r", None), ((4.5, 5.2), 8, 20)),
    ("wheel", ("click", (8.7, 3.9)), ("wheel", "chassis", "wh"), ((8.7, 4.1), 10, 16)),
)


def pinks(img, st):
    out = {}
    for tool, _, _, (p, hw, hh) in CASES:
        x, y = to_screen(st, p)
        out[tool] = pink_pixels(img, x - hw, y - hh, x + hw, y + hh)
    return out


@pytest.mark.slow
def test_each_joint_tool_draws_undoes_duplicates_and_saves(launch, tmp_path):
    scene = joints_scene(tmp_path / "joints.json")
    app = launch(scene, "--paused")
    st0 = app.wait_ready(20)
    names = ids(st0)
    before = pinks(app.screenshot("no_joints"), st0)
    made = []
    for k, (tool, use, (kind, a, b), _) in enumerate(CASES):
        pick_tool(app, tool)
        if use[0] == "click":
            app.click(*to_screen(st0, use[1]))
        else:
            app.drag(to_screen(st0, use[1]), to_screen(st0, use[2]), steps=12)
            app.xdo("mouseup", 1)
        st, j = new_joint(app, k + 1, f"the {tool} tool's joint")
        assert (j["kind"], j["a"], j["b"]) == (kind, names[a], None if b is None else names[b]), (tool, j)
        assert st["selected_joints"] == [j["id"]], "a new joint is selected"
        made.append(j)
    by_tool = {c[0]: j for c, j in zip(CASES, made)}
    assert by_tool["motor"]["params"]["max_motor_torque"] > 0 and by_tool["motor"]["params"]["motor_speed"] != 0
    assert by_tool["slider"]["params"]["upper"] == pytest.approx(2.5, abs=0.05)
    assert by_tool["rope"]["params"]["max_length"] == pytest.approx(3.5, abs=0.05)
    assert by_tool["wheel"]["params"]["spring_hertz"] > 0
    app.key("Escape")                      # deselect: every joint in its own colour
    st = app.frames(4)
    drawn = pinks(app.screenshot("joints"), st)
    for tool in drawn:
        assert drawn[tool] > before[tool] + 25, f"the {tool} joint is not drawn ({drawn} vs {before})"
    # select a joint by clicking its pin with the select tool
    app.key("1")
    app.click(*to_screen(st0, (-8.0, 4.3)))
    st = app.wait(lambda s: s["selected_joints"] == [by_tool["hinge"]["id"]], 10, "the hinge selected")
    assert "inspector:joint" in st["ui_rects"], "the inspector shows the joint"
    app.key("Delete")                      # a selected joint is deleted alone; undo brings it back
    st = app.wait(lambda s: s["n_joints"] == len(CASES) - 1, 10, "the hinge deleted")
    assert st["n_bodies"] == len(st0["bodies"]) and by_tool["hinge"]["id"] not in {j["id"] for j in st["joints"]}
    app.key("ctrl+z")
    st = app.wait(lambda s: s["n_joints"] == len(CASES), 10, "the hinge back")
    # undo every creation (newest first), then redo them all
    app.key("Escape")
    for n in range(len(CASES) - 1, -1, -1):
        app.key("ctrl+z")
        app.wait(lambda s, n=n: s["n_joints"] == n, 10, f"undo to {n} joints")
    st = app.frames(4)
    gone = pinks(app.screenshot("undone"), st)
    for tool in gone:
        assert gone[tool] <= before[tool] + 5, f"the undone {tool} joint is still drawn ({gone})"
    for n in range(1, len(CASES) + 1):
        app.key("ctrl+shift+z")
        app.wait(lambda s, n=n: s["n_joints"] == n, 10, f"redo to {n} joints")
    st = app.status()
    assert sorted((j["kind"], j["a"], j["b"]) for j in st["joints"]) == \
        sorted((j["kind"], j["a"], j["b"]) for j in made), "redo brings back the same joints"
    # duplicate the welded pair: the weld between them comes along (Ctrl+D), and undo
    app.drag(to_screen(st0, (-2.8, 5.2)), to_screen(st0, (-0.6, 3.2)), steps=10)   # box select f1, f2
    app.xdo("mouseup", 1)
    app.wait(lambda s: sorted(s["selection"]) == sorted([names["f1"], names["f2"]]), 10, "f1 and f2 selected")
    app.key("ctrl+d")
    st = app.wait(lambda s: s["n_joints"] == len(CASES) + 1, 10, "the duplicated weld")
    dup = max(st["joints"], key=lambda j: j["id"])
    assert dup["kind"] == "weld" and {dup["a"], dup["b"]}.isdisjoint({names["f1"], names["f2"]}), dup
    app.key("ctrl+z")
    app.wait(lambda s: s["n_joints"] == len(CASES) and s["n_bodies"] == len(st0["bodies"]), 10, "undo duplicate")
    # saved in the scene (Ctrl+S writes the document's own file)
    app.xdo("mousemove", *map(int, to_screen(st0, (0.0, 7.0))))
    app.settle()
    app.key("ctrl+s")
    app.wait(lambda s: not s["dirty"], 15, "the save")
    saved = json.loads(scene.read_text())
    assert sorted(j["kind"] for j in saved["joints"]) == sorted(c[2][0] for c in CASES)
    assert not st["gl_errors"] and not st["fault"]


def test_motor_speed_edited_live_turns_the_body(launch, tmp_path):
    app = launch(joints_scene(tmp_path / "joints.json"), "--paused")
    st0 = app.wait_ready(20)
    pick_tool(app, "motor")
    app.click(*to_screen(st0, (-5.0, 4.0)))
    st, j = new_joint(app, 1, "the motor hinge")
    assert st["selected_joints"] == [j["id"]]
    m = ids(st0)["m"]

    def spin(st):
        return next(b for b in st["bodies"] if b["id"] == m)["angular_velocity"]

    def set_speed(value, keys):
        """Type ``keys`` into the inspector's motor speed field (Enter applies it)."""
        st = app.wait(lambda s: "inspector:joint:motor_speed" in s["ui_rects"], 10, "the motor speed field")
        x0, y0, x1, y1 = st["ui_rects"]["inspector:joint:motor_speed"]
        app.click(x0 + 40, (y0 + y1) / 2)
        app.frames(3)
        app.key("ctrl+a", "BackSpace", *keys, "Return")
        return app.wait(lambda s: s["joints"] and s["joints"][0]["params"]["motor_speed"] == value, 10,
                        f"motor speed {value}")

    set_speed(5.0, ["5"])
    app.xdo("mousemove", *map(int, to_screen(st0, (0.0, 7.0))))     # back in the scene: its keys again
    app.settle()
    app.key("space")
    st = app.wait(lambda s: s["running"] and s["steps"] > st0["steps"] + 60, 60, "a second of running")
    img0 = app.screenshot("turning0")
    # the motor holds 5 rad/s (its 50 N m is ample for a 0.48 kg bar): within 1 % (issue 14's motor bound)
    assert spin(st) == pytest.approx(5.0, rel=0.01), st["joints"]
    a0, t0 = next(b for b in st["bodies"] if b["id"] == m)["angle"], st["time"]
    st = app.wait(lambda s: s["time"] > t0 + 0.3, 30, "more running")
    a1, t1 = next(b for b in st["bodies"] if b["id"] == m)["angle"], st["time"]
    assert (a1 - a0) / (t1 - t0) == pytest.approx(5.0, rel=0.02)
    img1 = app.screenshot("turning1")
    x, y = map(int, to_screen(st0, (-5.0, 4.0)))
    changed = np.count_nonzero(np.abs(img1[y - 30:y + 30, x - 30:x + 30] - img0[y - 30:y + 30, x - 30:x + 30]).sum(-1) > 60)
    assert changed > 150, "the bar is not drawn turning"
    # a live edit while running: the other way round
    set_speed(-3.0, ["minus", "3"])
    st = app.wait(lambda s: abs(spin(s) + 3.0) < 0.03, 20, "the bar turning at -3 rad/s")
    assert not st["gl_errors"] and not st["fault"]
