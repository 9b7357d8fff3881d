"""Issue 16, "a pleasant palette by default": bodies without a colour of their own are drawn in
the default palette by body id (app.render.colors.DEFAULT_PALETTE, several hues), with the
state colours kept clearly apart: selected (orange blend), hovered (lighter), sleeping (dimmed)."""
from __future__ import annotations

import numpy as np
import pytest

from app.render.colors import DEFAULT_PALETTE, asleep
from app.body_colors import hex_to_rgb
from test_look import box_pixels, near
from test_tools import body, tools_scene

pytestmark = pytest.mark.app


def default_rgb(b):
    """The fill of body ``b`` (a status entry) in 0-255: its palette colour by id."""
    return tuple(round(255 * v) for v in hex_to_rgb(DEFAULT_PALETTE[b["id"] % len(DEFAULT_PALETTE)]))


def test_default_palette_and_state_colours(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st = app.wait_ready(10)
    app.xdo("mousemove", 700, 120)      # off every body: no hover
    st = app.settle()
    img = app.screenshot("palette")
    boxes = [body(st, n) for n in ("a", "b", "c")]
    hues = {default_rgb(b) for b in boxes}
    assert len(hues) == 3, "neighbouring bodies share a hue"
    for b in boxes:
        assert near(box_pixels(img, st, b, 0.4), default_rgb(b)) > 0.8, f"{b['name']} not in its palette colour"
    # selected: the orange blend, far from every palette colour
    a = boxes[0]
    app.click(*map(int, a["screen"]))
    st = app.wait(lambda s: s["selection"] == [a["id"]], 10, "a selected")
    app.xdo("mousemove", 700, 120)
    st = app.settle()
    sel = box_pixels(app.screenshot("selected"), st, a, 0.4)
    assert max(near(sel, h) for h in hues) < 0.05, "the selection does not show"
    assert sel[:, 0].mean() > sel[:, 2].mean() + 20, "the selected body is not orange-tinted"
    app.key("Escape")
    st = app.wait(lambda s: not s["selection"], 10, "the selection cleared")
    # hovered: lighter than its own colour
    app.xdo("mousemove", *map(int, a["screen"]))
    app.settle()
    hov = box_pixels(app.screenshot("hovered"), st, a, 0.4)
    assert hov.mean() > np.mean(default_rgb(a)) + 8, "no hover tint"
    # sleeping: a and b come to rest on the ground; their colour dims (c swings on its spring)
    app.xdo("mousemove", 700, 120)
    app.key("space")
    st = app.wait(lambda s: not body(s, "a")["awake"] and not body(s, "b")["awake"], 60, "a and b asleep")
    app.key("space")
    st = app.settle()
    img = app.screenshot("asleep")
    for b in (body(st, "a"), body(st, "b")):
        dim = tuple(np.round(255 * asleep(np.array(default_rgb(b)) / 255.0)))
        px = box_pixels(img, st, b, 0.4)
        assert near(px, dim, 16) > 0.8, f"{b['name']} asleep is not drawn dimmed"
        assert near(px, default_rgb(b)) < 0.05
    assert not st["gl_errors"]
