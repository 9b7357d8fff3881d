"""Issue 16, "tracers": a trail behind a point of a body, from the tracer tool or the body's
right-click menu, kept for the trail length (world seconds), drawn fading, cleared on reset."""
from __future__ import annotations

import math

import numpy as np
import pytest

from test_compare import centre
from test_tools import body, to_screen, tools_scene

pytestmark = pytest.mark.app


def magenta(img, rect) -> int:
    """Trail pixels of the first tracer (app.tracers.TRAIL_COLORS[0], #ff59bf, fading)."""
    x0, y0, x1, y1 = map(int, rect)
    a = img[max(0, y0):y1, max(0, x0):x1]
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    return int(np.count_nonzero((r > 90) & (r > g + 50) & (b > g + 20)))


def local_to_world(b, local):
    c, s = math.cos(b["angle"]), math.sin(b["angle"])
    return (b["position"][0] + c * local[0] - s * local[1], b["position"][1] + s * local[0] + c * local[1])


@pytest.mark.slow
def test_tracer_tool_context_menu_trail_length_and_reset(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st = app.wait_ready(10)
    c, a = body(st, "c"), body(st, "a")
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("7")
    st = app.wait(lambda s: s["tool"] == "tracer", 10, "the tracer tool")
    app.click(*map(int, to_screen(st, (0.3, 3.3))))          # near c's top right corner
    st = app.wait(lambda s: len(s["tracers"]) == 1, 10, "a tracer on c")
    tr = st["tracers"][0]
    assert tr["body"] == c["id"] and tr["local"] == pytest.approx((0.3, 0.3), abs=0.05)
    # the right-click menu of box a: trace this point
    ax, ay = map(int, to_screen(st, (-4.0, 0.9)))
    app.xdo("mousemove", ax, ay)
    app.settle()
    app.xdo("mousedown", 3)
    app.settle()
    app.xdo("mouseup", 3)
    st = app.wait(lambda s: s["context_menu"] and "ctx:trace" in s["ui_rects"], 10, "the context menu")
    app.click(*centre(st["ui_rects"]["ctx:trace"]))
    st = app.wait(lambda s: len(s["tracers"]) == 2, 10, "a tracer on a")
    assert st["tracers"][1]["body"] == a["id"]
    # play for longer than the trail is kept
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    st = app.wait(lambda s: s["time"] > st["trail_seconds"] + 1.5, 120, "a few seconds of play")
    app.key("space")
    st = app.wait(lambda s: not s["running"], 10, "paused")
    st = app.settle()
    tr = st["tracers"][0]
    dt = st["dt"]
    assert tr["n"] > 30 and st["trail_seconds"] - 4 * dt <= tr["span"] <= st["trail_seconds"] + 1e-9, tr
    c = body(st, "c")
    assert tr["last"] == pytest.approx(local_to_world(c, tr["local"]), abs=1e-9), "the trail does not end at the point"
    img = app.screenshot("trails")
    cx, cy = to_screen(st, c["position"])
    s = st["camera"]["scale"]
    assert magenta(img, (cx - 2 * s, cy - 3 * s, cx + 2 * s, cy + 3 * s)) > 40, "no trail drawn behind c"
    # reset: the trails are cleared, the tracers follow the reset scene's bodies
    app.key("r")
    st = app.wait(lambda s: s["tracers"] and s["tracers"][0]["n"] <= 1, 20, "cleared trails")
    assert len(st["tracers"]) == 2 and st["tracers"][0]["body"] == body(st, "c")["id"]
    app.key("space")
    st = app.wait(lambda s: s["tracers"][0]["n"] > 10, 60, "a new trail after the reset")
    assert not st["gl_errors"]
