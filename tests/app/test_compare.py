"""Issue 16, "compare solvers side by side, live": the open scene runs in a second mode beside the
main one, drawn as ghost outlines over it or in a split pane of its own, and every lane's step
time, energy drift, penetration and drift from the main world are plotted together."""
from __future__ import annotations

import math

import numpy as np
import pytest

from sandbox_pixels import ROOT, body_mask, body_pixels

pytestmark = pytest.mark.app


def centre(rect):
    x0, y0, x1, y1 = rect
    return int((x0 + x1) / 2), int((y0 + y1) / 2)


def lane_pixels(img, rect) -> int:
    """Pixels of the first rival's colour (orange, app.compare.LANE_COLORS[1]): its outlines and,
    in split view, its darker fill."""
    x0, y0, x1, y1 = map(int, rect)
    a = img[max(0, y0):y1, max(0, x0):x1]
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    return int(np.count_nonzero((r > 120) & (r - b > 80) & (g > 0.45 * r) & (g < 0.8 * r)))


def open_section(app, st, title):
    app.click(*centre(st["ui_rects"][f"section:{title}"]))
    return app.settle()


def test_compare_ghost_and_split_views_with_plots(launch):
    app = launch(ROOT / "scenes" / "pyramid.json")
    st = app.wait_ready(20)
    main_solver = st["solver"]
    rival = "sequential_impulse" if main_solver != "sequential_impulse" else "soft_step"
    before = app.screenshot("before")
    free = st["free_rect"]
    assert lane_pixels(before, free) < 50, "orange in the scene before any comparison"
    st = open_section(app, st, "Compare solvers")
    app.click(*centre(st["ui_rects"][f"compare:mode:{rival}"]))
    st = app.settle()
    app.click(*centre(st["ui_rects"]["compare:start"]))
    # 4 s of the rival's steps: its step-time line must span enough of the plot's 25 s to be seen
    # (with a cold cache the rival starts only once its kernels are compiled)
    st = app.wait(lambda s: s["compare"]["active"] and len(s["compare"]["lanes"]) == 2
                  and s["compare"]["lanes"][1]["steps"] > 240, 900, "the rival's steps (its kernels compile first)")
    main, other = st["compare"]["lanes"]
    assert other["solver"] == rival and other["label"].startswith(rival)
    assert other["steps"] > 240 and abs(other["steps"] - main["steps"]) <= 8 + other["behind"], \
        "the rival does not keep up with the main world"
    assert main["step_ms"] > 0 and other["step_ms"] > 0
    for lane in (main, other):
        assert math.isfinite(lane["energy"]) and math.isfinite(lane["pen"]) and lane["pen"] >= 0
    assert main["drift"] == 0.0 and math.isfinite(other["drift"]) and other["drift"] >= 0.0
    titles = [p["title"] for p in st["compare_plots"]]
    assert titles == ["step time (ms)", "energy drift (J)", "max penetration (m)", "drift from main (m)"]
    for p in st["compare_plots"]:
        x0, y0, x1, y1 = p["rect"]
        assert x1 - x0 > 90 and y1 - y0 > 60, p
    # ghost view: the rival's bodies are orange outlines over the scene
    ghost = app.screenshot("ghost")
    assert lane_pixels(ghost, free) > 400, "no ghost outlines of the rival"
    # the plots: one line per lane in the lane's colour (orange for the rival) inside the plot area
    x0, y0, x1, y1 = map(int, st["compare_plots"][0]["rect"])
    assert lane_pixels(ghost, (x0, y0, x1, y1)) > 20, "the rival's step-time line is not drawn"
    # split view: the main world in the left half of the free area, the rival in the right half
    app.click(*centre(st["ui_rects"]["compare:view:split"]))
    st = app.wait(lambda s: s["compare"]["view"] == "split", 10, "split view")
    st = app.settle()
    split = app.screenshot("split")
    fx0, fy0, fx1, fy1 = st["free_rect"]
    xm = (fx0 + fx1) / 2
    left, right = (fx0, fy0, xm - 4, fy1), (xm + 4, fy0, fx1, fy1)
    assert body_pixels(split, *map(int, (left[0], left[2], left[1], left[3]))) > 2000, "no main world on the left"
    assert lane_pixels(split, right) > 2000, "no rival on the right"
    assert np.count_nonzero(body_pixels_mask(split, right)) < 0.1 * lane_pixels(split, right), \
        "main-world bodies in the rival's pane"
    # both panes show the same part of the world: the rival's pile sits where the main one does
    lc = np.argwhere(body_pixels_mask(split, left))
    rc = np.argwhere(lane_mask(split, right))
    assert abs(lc[:, 1].mean() - rc[:, 1].mean()) < 40 and abs(lc[:, 0].mean() - rc[:, 0].mean()) < 40
    # an edit restarts the rival from the scene as it is then
    r0 = st["compare"]["restarts"]
    app.xdo("mousemove", int((left[0] + left[2]) / 2), int(left[1] + 20))
    app.settle()
    app.key("ctrl+d")      # nothing selected: no edit, no restart
    app.key("r")           # reset: a new document, the rivals start again from it
    st = app.wait(lambda s: s["compare"]["restarts"] > r0, 20, "the restart after reset")
    assert st["compare"]["active"] and not st["gl_errors"]


def body_pixels_mask(img, rect):
    """The main world's dynamic bodies (any palette colour; the rival's static grey is the same)."""
    x0, y0, x1, y1 = map(int, rect)
    return body_mask(img, x0, x1, y0, y1, static=False)


def lane_mask(img, rect):
    x0, y0, x1, y1 = map(int, rect)
    a = img[y0:y1, x0:x1]
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    return (r > 120) & (r - b > 80) & (g > 0.45 * r) & (g < 0.8 * r)
