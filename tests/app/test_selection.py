"""Issue 16: box select on empty space, move and rotate the selection with its handles, copy and
paste at the pointer, grid and angle snapping, camera follow of a selected body."""
from __future__ import annotations

import math

import numpy as np
import pytest

from test_tools import body, to_screen, tools_scene

pytestmark = pytest.mark.app


def ids(st, *names):
    return sorted(body(st, n)["id"] for n in names)


def test_box_select_handles_copy_paste_and_snapping(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st = app.wait_ready(10)
    # box select: a drag on empty space from above-left of a to below-right of b (not c, up high)
    app.drag(to_screen(st, (-5.5, 2.2)), to_screen(st, (5.5, 0.1)), steps=12)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: sorted(s["selection"]) == ids(s, "a", "b"), 10, "a and b box-selected")
    a0, b0 = body(st, "a"), body(st, "b")
    # the move handle (the selection box's centre) moves both; snapping off: by the drag exactly
    centre = (0.0, 0.6)
    app.drag(to_screen(st, centre), to_screen(st, (0.0, 2.6)), steps=10)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: body(s, "a")["position"][1] > 2.0, 10, "the moved selection")
    st = app.settle()
    for name, p0 in (("a", a0), ("b", b0)):
        p = body(st, name)["position"]
        assert p[0] == pytest.approx(p0["position"][0], abs=0.05) and p[1] == pytest.approx(2.6, abs=0.05)
    app.key("ctrl+z")                      # one undo puts both back
    st = app.wait(lambda s: body(s, "a")["position"][1] < 1.0, 10, "the undone move")
    assert body(st, "b")["position"][1] == pytest.approx(b0["position"][1], abs=1e-9)
    # rotate handle (above the box) with snapping on (G): a quarter turn lands on 90 degrees
    app.xdo("mousemove", 700, 100)
    app.settle()
    app.key("g")
    st = app.wait(lambda s: s["snap"]["on"], 10, "snapping on")
    s = st["camera"]["scale"]
    knob = to_screen(st, (0.0, 1.2 + 30.0 / s))
    cx, cy = to_screen(st, centre)
    r = knob[1] - cy                       # negative: the knob is above (screen y down)
    app.drag(knob, (cx - r + 3, cy + 2), steps=16)   # a quarter turn clockwise on screen
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: abs(body(s, "a")["angle"]) > 0.5, 10, "the rotated selection")
    st = app.settle()
    for name in ("a", "b"):
        assert body(st, name)["angle"] == pytest.approx(-math.pi / 2, abs=1e-9), "not snapped to 15 degrees"
    # rotated about the centre: a (left of it) is now above it
    a1 = body(st, "a")["position"]
    assert a1[0] == pytest.approx(centre[0], abs=0.05) and a1[1] == pytest.approx(centre[1] + 4.0, abs=0.05)
    app.key("ctrl+z")
    st = app.wait(lambda s: abs(body(s, "a")["angle"]) < 1e-9, 10, "the undone rotation")
    # copy and paste at the pointer (snapped to the 0.5 m grid)
    app.key("ctrl+c")
    st = app.wait(lambda s: s["clipboard"] == 2, 10, "two bodies copied")
    target = to_screen(st, (1.1, 6.2))
    app.xdo("mousemove", *map(int, target))
    app.settle()
    app.key("ctrl+v")
    st = app.wait(lambda s: s["n_bodies"] == 6, 10, "the pasted copy")
    new = [b for b in st["bodies"] if (b["name"] or "").endswith(" copy")]     # copies keep their names
    assert sorted(b["name"] for b in new) == ["a copy", "b copy"]
    assert len(new) == 2 and sorted(st["selection"]) == sorted(b["id"] for b in new)
    mid = np.mean([b["position"] for b in new], axis=0)
    assert mid == pytest.approx((1.0, 6.0), abs=1e-6), "the copy's centre is not at the (snapped) pointer"
    # snapping a creation tool: a box drawn off-grid gets grid corners
    app.key("2")
    app.drag(to_screen(st, (-6.12, 4.13)), to_screen(st, (-4.9, 5.4)), steps=8)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: s["n_bodies"] == 7, 10, "the snapped box")
    box = max(st["bodies"], key=lambda b: b["id"])
    assert box["position"] == pytest.approx((-5.5, 4.75), abs=1e-9)
    assert not st["gl_errors"]


def test_camera_follows_the_selected_body(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st = app.wait_ready(10)
    c = body(st, "c")
    app.click(*map(int, c["screen"]))
    st = app.wait(lambda s: s["selection"] == [c["id"]], 10, "c selected")
    app.key("l")
    st = app.wait(lambda s: s["follow"] == c["id"], 10, "following c")
    # drop c off its spring: select the spring and delete it, then play; c falls, the camera follows
    app.click(*map(int, to_screen(st, (0.0, 5.3))))
    st = app.wait(lambda s: s["selection"] and s["selection"][0] != c["id"], 10, "the spring selected")
    app.key("Delete")
    st = app.wait(lambda s: s["n_springs"] == 0, 10, "the spring deleted")
    app.key("space")
    st = app.wait(lambda s: s["time"] > 0.5, 60, "c falling")
    for _ in range(3):
        st = app.frames(4)
        cs = body(st, "c")
        fx0, fy0, fx1, fy1 = st["free_rect"]
        # the status is written after a frame: c is where the camera put it, give or take a step
        assert cs["screen"][0] == pytest.approx((fx0 + fx1) / 2, abs=3)
        assert cs["screen"][1] == pytest.approx((fy0 + fy1) / 2, abs=0.5 * 9.81 * st["camera"]["scale"] / 20)
    assert not st["gl_errors"]
