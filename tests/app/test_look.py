"""Issue 16, "a look people enjoy": a body's own colour from the inspector's palette, drawn with
the state colours kept (selected, hovered, sleeping); a reset goes back to the file's colours."""
from __future__ import annotations

import json

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


@pytest.mark.slow
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
    # a reset goes back to the file's colours: the file gave a none, so the unsaved green goes
    app.xdo("mousemove", 700, 120)
    app.settle()
    reset_discarding(app)
    st = app.settle()
    img = app.screenshot("after_reset")
    assert body(st, "a")["color"] is None, "the reset kept an unsaved colour"
    assert near(box_pixels(img, st, body(st, "a")), GREEN) < 0.05, "the reset drew the unsaved colour"
    # a saved colour is the file's: a reset keeps it and drops a later, unsaved one
    set_swatch(app, body(st, "a"), 3)
    app.key("ctrl+s")
    st = app.wait(lambda s: not s["dirty"], 10, "the save")
    set_swatch(app, body(st, "b"), 1)
    app.xdo("mousemove", 700, 120)
    app.settle()
    reset_discarding(app)
    st = app.settle()
    img = app.screenshot("after_save_reset")
    assert body(st, "a")["color"] == "#81b29a" and body(st, "b")["color"] is None
    assert near(box_pixels(img, st, body(st, "a")), GREEN) > 0.8, "the reset lost a's saved colour"
    assert near(box_pixels(img, st, body(st, "b")), CORAL) < 0.05, "the reset kept b's unsaved colour"
    assert not st["gl_errors"]


def set_swatch(app, b, k):
    """Select body ``b`` and click the inspector's swatch ``k`` (app.render.colors.PALETTE), then
    clear the selection."""
    app.click(*map(int, b["screen"]))
    st = app.wait(lambda s: s["selection"] == [b["id"]], 10, f"{b['name']} selected")
    st = app.settle()
    app.click(*centre(st["ui_rects"][f"inspector:swatch:{k}"]))
    app.wait(lambda s: body(s, b["name"])["color"] is not None and s["dirty"], 10, "the colour set")
    app.xdo("mousemove", 700, 120)
    app.settle()
    app.key("Escape")
    app.wait(lambda s: not s["selection"], 10, "the selection cleared")


def reset_discarding(app):
    """R with unsaved edits asks first: discard them; the document is then clean at time 0."""
    app.key("r")
    st = app.wait(lambda s: s["dialog"] == "Unsaved edits", 10, "the question")
    st = app.settle()
    app.click(*centre(st["ui_rects"]["dialog:Discard edits"]))
    app.wait(lambda s: s["time"] == 0.0 and not s["dirty"], 10, "the reset")


CORAL = (224, 122, 95)     # "#e07a5f", the scene file's colour for b


def test_scene_colours_load_undo_and_save(launch, tmp_path):
    """A colour from the scene file is drawn; an inspector colour is undone and redone with
    Ctrl+Z / Ctrl+Shift+Z; Ctrl+S writes both into the file as "#rrggbb"."""
    path = tools_scene(tmp_path / "coloured.json")
    data = json.loads(path.read_text())
    data["bodies"][2]["color"] = "#e07a5f"
    path.write_text(json.dumps(data))
    app = launch(path, "--paused")
    st = app.wait_ready(10)
    a, b = body(st, "a"), body(st, "b")
    assert b["color"] == "#e07a5f" and a["color"] is None
    img = app.screenshot("loaded")
    assert near(box_pixels(img, st, b), CORAL) > 0.8, "b is not drawn in the file's colour"
    assert near(box_pixels(img, st, a), CORAL) < 0.05 and near(box_pixels(img, st, a), GREEN) < 0.05
    app.click(*map(int, a["screen"]))
    st = app.wait(lambda s: s["selection"] == [a["id"]], 10, "a selected")
    st = app.settle()
    app.click(*centre(st["ui_rects"]["inspector:swatch:3"]))
    st = app.wait(lambda s: body(s, "a")["color"] == "#81b29a" and s["dirty"], 10, "a's colour set")
    app.xdo("mousemove", 700, 120)
    app.settle()
    app.key("Escape")
    st = app.wait(lambda s: not s["selection"], 10, "the selection cleared")
    st = app.settle()
    assert near(box_pixels(app.screenshot("green"), st, a), GREEN) > 0.8
    app.key("ctrl+z")
    st = app.wait(lambda s: body(s, "a")["color"] is None, 10, "the colour undone")
    st = app.settle()
    img = app.screenshot("undone")
    assert near(box_pixels(img, st, a), GREEN) < 0.05, "the undo left a green"
    assert near(box_pixels(img, st, b), CORAL) > 0.8, "the undo touched b"
    app.key("ctrl+shift+z")
    st = app.wait(lambda s: body(s, "a")["color"] == "#81b29a", 10, "the colour redone")
    app.key("ctrl+s")
    st = app.wait(lambda s: not s["dirty"], 10, "the save")
    saved = {x["name"]: x.get("color") for x in json.loads(path.read_text())["bodies"]}
    assert saved == {"ground": None, "a": "#81b29a", "b": "#e07a5f", "c": None}, saved
    assert not st["gl_errors"]
