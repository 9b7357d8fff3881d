"""Issue 16, "a look people enjoy": a body's own colour from the inspector's palette, drawn with
the state colours kept (selected, hovered, sleeping), and kept by a reset."""
from __future__ import annotations

import numpy as np
import pytest

from test_compare import centre
from test_tools import body, to_screen, tools_scene

pytestmark = pytest.mark.app

GREEN = (129, 178, 154)    # app.render.colors.PALETTE[3], #81b29a (a sage green)


def box_pixels(img, st, b, half=0.45):
    """The pixels inside body ``b`` (a 1.2 m box of tools_scene), a margin off its outline."""
    cx, cy = to_screen(st, b["position"])
    r = half * st["camera"]["scale"]
    return img[int(cy - r):int(cy + r), int(cx - r):int(cx + r)].reshape(-1, 3)


def near(px, rgb, tol=30) -> float:
    """The share of pixels within ``tol`` of ``rgb`` in every channel."""
    return float(np.mean(np.all(np.abs(px - np.array(rgb)) < tol, axis=1)))


def test_own_colour_with_state_colours_kept(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st = app.wait_ready(10)
    a = body(st, "a")
    app.click(*map(int, a["screen"]))
    st = app.wait(lambda s: s["selection"] == [a["id"]], 10, "a selected")
    st = app.settle()
    app.click(*centre(st["ui_rects"]["inspector:swatch:3"]))
    st = app.settle()
    selected = app.screenshot("selected")
    app.xdo("mousemove", 700, 120)      # off every body: no hover
    app.settle()
    app.key("Escape")                   # nothing selected
    st = app.wait(lambda s: not s["selection"], 10, "the selection cleared")
    st = app.settle()
    img = app.screenshot("coloured")
    assert near(box_pixels(img, st, a), GREEN) > 0.8, "a is not drawn in its own colour"
    b = body(st, "b")
    assert near(box_pixels(img, st, b), GREEN) < 0.05, "b took a's colour"
    # selected: the selection colour is blended over the own colour (a differs from plain coral)
    assert near(box_pixels(selected, st, a), GREEN) < 0.2, "the selection does not show on a coloured body"
    # hovered: lighter than the own colour
    app.xdo("mousemove", *map(int, a["screen"]))
    app.settle()
    hovered = app.screenshot("hovered")
    assert box_pixels(hovered, st, a).mean() > box_pixels(img, st, a).mean() + 8, "no hover tint"
    # a reset keeps the colour (the body at the same place in the scene)
    app.xdo("mousemove", 700, 120)
    app.settle()
    app.key("r")
    st = app.wait(lambda s: s["time"] == 0.0 and not s["dirty"], 10, "the reset")
    st = app.settle()
    img = app.screenshot("after_reset")
    assert near(box_pixels(img, st, body(st, "a")), GREEN) > 0.8, "the reset lost a's colour"
    assert not st["gl_errors"]
