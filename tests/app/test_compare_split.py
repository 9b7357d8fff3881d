"""Split view with two rivals draws all three worlds, each in its own column; after "Stop
comparing" the scene is framed in the whole free area again, without pressing F."""
from __future__ import annotations

import numpy as np
import pytest

from sandbox_pixels import ROOT
from test_compare import body_pixels_mask, centre, lane_mask, open_section

pytestmark = pytest.mark.app

RIVALS = ("sequential_impulse", "impulse")


def green_mask(img, rect):
    """The second rival's colour (app.compare.LANE_COLORS[2], green), outlines and darker fill."""
    x0, y0, x1, y1 = map(int, rect)
    a = img[y0:y1, x0:x1].astype(int)
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    return (g > 90) & (g - r > 35) & (g - b > 25)


def test_split_view_draws_every_rival_and_stop_frames_the_scene_again(launch):
    app = launch(ROOT / "scenes" / "pyramid.json")
    st = app.wait_ready(20)
    scale0 = st["camera"]["scale"]
    st = open_section(app, st, "Compare solvers")
    for mode in RIVALS:
        app.click(*centre(st["ui_rects"][f"compare:mode:{mode}"]))
        st = app.settle()
    app.click(*centre(st["ui_rects"]["compare:start"]))
    st = app.wait(lambda s: s["compare"]["active"] and len(s["compare"]["lanes"]) == 3
                  and min(ln["steps"] for ln in s["compare"]["lanes"][1:]) > 30, 900, "both rivals stepping")
    app.click(*centre(st["ui_rects"]["compare:view:split"]))
    app.wait(lambda s: s["compare"]["view"] == "split", 10, "split view")
    st = app.settle()
    img = app.screenshot("split_three")
    fx0, fy0, fx1, fy1 = st["free_rect"]
    w = (fx1 - fx0) / 3
    cols = [(fx0 + k * w + 4, fy0, fx0 + (k + 1) * w - 4, fy1) for k in range(3)]
    assert np.count_nonzero(body_pixels_mask(img, cols[0])) > 1000, "no main world in the left column"
    assert np.count_nonzero(lane_mask(img, cols[1])) > 1000, f"no {RIVALS[0]} in the middle column"
    assert np.count_nonzero(green_mask(img, cols[2])) > 1000, f"no {RIVALS[1]} in the right column"
    split_scale = st["camera"]["scale"]
    assert split_scale < 0.6 * scale0, (split_scale, scale0)
    app.click(*centre(st["ui_rects"]["compare:stop"]))
    st = app.wait(lambda s: not s["compare"]["active"], 10, "the comparison stopped")
    st = app.settle()
    assert st["camera"]["scale"] > 1.5 * split_scale, "the view stayed framed for the left column"
    img = app.screenshot("stopped")
    right_half = (int((fx0 + fx1) / 2), fy0, fx1, fy1)
    assert np.count_nonzero(body_pixels_mask(img, right_half)) > 1000, "the scene does not fill the free area"
