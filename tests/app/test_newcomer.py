"""Issue 16, items 6, 8 and 10 (autosave): the polygon tool says why it refuses, at the pointer;
a solver switch wakes the world, reset keeps the solver, each mode says what it is good and bad
at; a second instance does not offer the running one's autosave."""
from __future__ import annotations

import os
import signal
import time

import numpy as np
import pytest

from sandbox_pixels import ROOT
from test_saving import scene_point
from test_tools import new_bodies, to_screen, tools_scene

pytestmark = pytest.mark.app


def hint_pixels(img, rect) -> int:
    """Red or amber text of the hint window."""
    x0, y0, x1, y1 = map(int, rect)
    a = img[max(0, y0):y1, max(0, x0):x1]
    r, b = a[..., 0], a[..., 2]
    return int(np.count_nonzero((r > 200) & (b < 150) & (r - b > 80)))


def test_polygon_tool_says_why_at_the_pointer(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st0 = app.wait_ready(10)
    n0 = st0["n_bodies"]
    app.key("3")
    app.settle()
    p1, p2 = to_screen(st0, (-3.0, 4.0)), to_screen(st0, (-1.0, 4.0))
    for p in (p1, p2):
        app.click(*map(int, p))
    app.key("Return")                                     # two points: refused, and said so
    st = app.wait(lambda s: s["hint"] and "at least 3 points" in s["hint"], 10, "the refusal")
    st = app.settle()
    assert st["n_bodies"] == n0
    img = app.screenshot("two_points")
    hx0, hy0, hx1, hy1 = st["ui_rects"]["hint"]
    assert abs(hx0 - p2[0]) < 60 and abs(hy1 - p2[1]) < 60, "the hint is not beside the last point"
    assert hint_pixels(img, st["ui_rects"]["hint"]) > 60, "the hint is not drawn"
    # a third point on the same line: no area, said so; the points are kept
    app.click(*map(int, to_screen(st0, (1.0, 4.0))))
    app.key("Return")
    st = app.wait(lambda s: s["hint"] and "zero area" in s["hint"], 10, "the no-area refusal")
    assert st["n_bodies"] == n0
    # a point off the line makes a triangle of the kept points (the middle one is dropped)
    app.click(*map(int, to_screen(st0, (-1.0, 6.0))))
    app.key("Return")
    st = app.wait(lambda s: s["n_bodies"] == n0 + 1, 10, "the polygon")
    (poly,) = new_bodies(st, st0)
    assert poly["vertices"] == 3
    # the outline is kept as drawn (issue 13: no silent convex hull); a convex one needs no word
    assert not st["hint"] or "convex hull" not in st["hint"], st["hint"]
    assert not st["gl_errors"]


def test_mode_switch_wakes_and_reset_keeps_the_solver(launch):
    app = launch(ROOT / "scenes" / "pyramid.json")
    st = app.wait_ready(10)
    st = app.wait(lambda s: s["awake"] <= 5, 120, "the pyramid to fall asleep")   # of 210 boxes
    desc = st["ui_values"]["solver_description"]
    assert "Extreme probes (docs/reliability.md): held" in desc and "degraded" in desc, desc
    x0, y0, x1, y1 = st["ui_rects"]["solver_combo"]
    app.click((x0 + x1) / 2, (y0 + y1) / 2)
    st = app.wait(lambda s: "solver:impulse" in s["ui_rects"], 10, "the mode list")
    st = app.settle()
    x0, y0, x1, y1 = st["ui_rects"]["solver:impulse"]
    app.click((x0 + x1) / 2, (y0 + y1) / 2)
    st = app.wait(lambda s: s["solver"] == "impulse", 120, "the impulse mode")    # once loaded
    assert st["awake"] > 100, f"the switch left the pyramid asleep ({st['awake']} awake)"
    desc = st["ui_values"]["solver_description"]
    assert "failed" in desc and "speed" in desc, desc
    img = app.screenshot("impulse_description")
    dx0, dy0, dx1, dy1 = map(int, st["ui_rects"]["solver_description"])
    assert int(np.count_nonzero(img[dy0:dy1, dx0:dx1].min(axis=2) > 140)) > 200, "the description is not drawn"
    app.xdo("mousemove", *scene_point(st))
    app.settle()
    app.key("r")                           # the switch is an edit: reset asks first
    st = app.wait(lambda s: s["dialog"] == "Unsaved edits", 10, "the question")
    st = app.settle()
    x0, y0, x1, y1 = st["ui_rects"]["dialog:Discard edits"]
    app.click((x0 + x1) / 2, (y0 + y1) / 2)
    st = app.wait(lambda s: any("reset to the loaded state" in m for m in s["messages"]), 20, "the reset")
    assert st["solver"] == "impulse", "reset reverted the solver"
    assert not st["gl_errors"]


@pytest.mark.slow
def test_second_instance_does_not_offer_the_running_ones_autosave(launch, tmp_path):
    cache = {"XDG_CACHE_HOME": str(tmp_path / "xdg_cache")}
    first = launch(tools_scene(tmp_path / "tools.json"), "--paused", "--autosave-interval", "0.5",
                   offer_autosave=True, env=cache, subdir="first")
    st = first.wait_ready(10)
    n0 = st["n_bodies"]
    first.key("2")
    first.click(*scene_point(st))
    first.wait(lambda s: s["n_bodies"] == n0 + 1, 10, "an edit")
    autosaves = tmp_path / "xdg_cache" / "stelkropp"
    deadline = time.monotonic() + 20
    while not list(autosaves.glob("autosave-*.json")) and time.monotonic() < deadline:
        time.sleep(0.2)
    assert list(autosaves.glob("autosave-*.json")), "the first instance wrote no autosave"
    second = launch(tools_scene(tmp_path / "tools2.json"), "--paused", offer_autosave=True, env=cache,
                    subdir="second")
    st = second.wait_ready(10)
    assert st["dialog"] is None and not st["autosave_offer"], "the running instance's autosave was offered"
    second.close()
    # the first one crashes: now its autosave is a crash recovery, offered to the next start
    os.kill(first.proc.pid, signal.SIGKILL)
    first.proc.wait(10)
    third = launch(tools_scene(tmp_path / "tools3.json"), "--paused", offer_autosave=True, env=cache,
                   subdir="third")
    st = third.wait(lambda s: s.get("autosave_offer"), 60, "the crash recovery offer")
    assert st["autosave_offer"]["origin"].endswith("tools.json")
