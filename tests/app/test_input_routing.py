"""Issue 16, item 3: every click and wheel event goes where it lands, in the frame it lands.

xdotool sends the move and the click in one command (microseconds apart), so both reach the
window in one frame: before the fix the scene judged the click by where the pointer was in the
previous frame.
"""
from __future__ import annotations

import pytest

from test_tools import body, tools_scene

pytestmark = pytest.mark.app


def centre(rect):
    x0, y0, x1, y1 = rect
    return int((x0 + x1) / 2), int((y0 + y1) / 2)


def test_click_on_a_panel_in_the_frame_the_pointer_arrives_is_the_panels(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st0 = app.wait_ready(20)
    n0 = st0["n_bodies"]
    app.key("2")                                             # the box tool
    scene_pt = (int(body(st0, "c")["screen"][0]) + 120, 250)  # empty space in the scene
    app.xdo("mousemove", *scene_pt)
    st = app.wait(lambda s: s["tool"] == "box", 10, "the box tool")
    app.settle()
    # from the scene straight onto the polygon button, and click, in one go
    bx, by = centre(st["ui_rects"]["tool:polygon"])
    app.xdo("mousemove", bx, by, "click", "1")
    st = app.wait(lambda s: s["tool"] == "polygon", 10, "the polygon tool")
    st = app.settle()
    assert st["n_bodies"] == n0, "the click on the button also created a box in the scene"
    # the wheel over a panel, in the frame the pointer arrives there, scrolls the panel only
    app.xdo("mousemove", *scene_pt)
    scale0 = app.settle()["camera"]["scale"]
    sx, sy = centre(st["ui_rects"]["main_window"])
    app.xdo("mousemove", sx, sy, "click", "4", "click", "4")
    st = app.settle()
    assert st["camera"]["scale"] == pytest.approx(scale0), "the wheel over the panel zoomed the scene"
    # and the other way: from a panel straight into the scene, the click is the scene's
    app.key("2")
    app.xdo("mousemove", bx, by)
    app.wait(lambda s: s["tool"] == "box", 10, "the box tool again")
    app.settle()
    app.xdo("mousemove", *scene_pt, "click", "1")
    st = app.wait(lambda s: s["n_bodies"] == n0 + 1, 10, "a box where the click landed")
    new = [b for b in st["bodies"] if b["id"] not in {q["id"] for q in st0["bodies"]}][0]
    assert abs(new["screen"][0] - scene_pt[0]) < 3 and abs(new["screen"][1] - scene_pt[1]) < 3, new
    app.xdo("mousemove", *scene_pt, "click", "5", "click", "5")   # the wheel in the scene zooms it
    st = app.wait(lambda s: s["camera"]["scale"] < 0.9 * scale0, 10, "zoom out in the scene")
    assert not st["gl_errors"] and not st["fault"]
