"""Issue 16, item 1: shipped scenes are read-only to the sandbox; saving one writes to the user's
scene folder (listed in the scene panel); overwriting any other existing file asks first; the
Save-as field follows the current scene."""
from __future__ import annotations

import json

import numpy as np
import pytest

from sandbox_pixels import ROOT

pytestmark = pytest.mark.app


def scene_point(st):
    """The middle of the free area between the panels (pixels, y down)."""
    x0, y0, x1, y1 = st["free_rect"]
    return int((x0 + x1) / 2), int((y0 + y1) / 2)


def text_pixels(img, rect) -> int:
    x0, y0, x1, y1 = map(int, rect)
    a = img[y0:y1, x0:x1]
    return int(np.count_nonzero(a.min(axis=2) > 170))


def centre(rect):
    x0, y0, x1, y1 = rect
    return int((x0 + x1) / 2), int((y0 + y1) / 2)


def test_read_only_scene_is_saved_to_the_user_folder(launch):
    shipped = ROOT / "scenes" / "tumbler.json"
    original, mtime = shipped.read_bytes(), shipped.stat().st_mtime_ns
    app = launch(shipped, "--paused")
    st = app.wait_ready(20)
    mine = app.user_scenes / "tumbler.json"
    assert st["save_as"] == str(mine), "the Save-as field does not follow the opened scene"
    app.xdo("mousemove", *scene_point(st))
    app.settle()
    app.key("ctrl+s")
    st = app.wait(lambda s: s["path"] == str(mine), 20, "the save to the user's folder")
    assert mine.exists() and shipped.read_bytes() == original and shipped.stat().st_mtime_ns == mtime
    assert any("read-only" in m and str(mine) in m for m in st["messages"]), st["messages"]
    assert st["user_scenes"] == [str(mine)] and st["save_as"] == str(mine)
    # an edit (a box), saved again: the document's own file is written without a question
    n0 = st["n_bodies"]
    app.key("2")
    app.click(*scene_point(st))
    st = app.wait(lambda s: s["n_bodies"] == n0 + 1 and s["dirty"], 10, "a new box")
    app.key("ctrl+s")
    st = app.wait(lambda s: not s["dirty"], 10, "the second save")
    assert st["dialog"] is None
    assert len(json.loads(mine.read_text())["bodies"]) == n0 + 1
    assert shipped.read_bytes() == original
    # the scene panel lists the user's scene under "yours"
    app.key("ctrl+shift+s")                 # opens the Scene section, keyboard in Save as
    st = app.wait(lambda s: f"scene:{mine}" in s["ui_rects"], 10, "the user's scene in the list")
    app.key("Escape")
    st = app.settle()
    img = app.screenshot("scene_list")
    assert text_pixels(img, st["ui_rects"][f"scene:{mine}"]) > 30, "the user's scene is not shown in the list"
    assert not st["gl_errors"]


def test_overwriting_an_existing_file_asks_first(launch, tmp_path):
    other = tmp_path / "mine.json"
    other.write_text((ROOT / "scenes" / "pyramid.json").read_text())
    before = other.read_text()
    app = launch(ROOT / "scenes" / "default.json", "--paused")
    st = app.wait_ready(20)
    assert st["save_as"] == str(app.user_scenes / "default.json")
    app.send("on_file_drop", 640, 400, [str(ROOT / "scenes" / "arch.json")])
    st = app.wait(lambda s: s["path"].endswith("arch.json"), 20, "arch.json open")
    assert st["save_as"] == str(app.user_scenes / "arch.json"), "the Save-as field still shows the last scene"
    # Save as onto an existing file: the question, then Cancel leaves the file alone
    app.xdo("mousemove", *scene_point(st))
    app.settle()
    app.key("ctrl+shift+s")
    app.settle()
    app.key("ctrl+a")
    app.xdo("type", "--delay", "20", str(other))
    app.key("Return")
    st = app.wait(lambda s: s["dialog"] == "Overwrite?", 10, "the overwrite question")
    st = app.settle()
    img = app.screenshot("overwrite_question")
    assert text_pixels(img, st["ui_rects"]["dialog:Overwrite"]) > 20, "the question is not drawn"
    app.click(*centre(st["ui_rects"]["dialog:Cancel"]))
    st = app.wait(lambda s: s["dialog"] is None, 10, "the dialog closed")
    assert other.read_text() == before and st["path"].endswith("arch.json")
    # again, and Overwrite: the file now holds the arch
    app.key("ctrl+shift+s")
    app.settle()
    app.key("Return")
    st = app.wait(lambda s: s["dialog"] == "Overwrite?", 10, "the overwrite question again")
    app.click(*centre(st["ui_rects"]["dialog:Overwrite"]))
    st = app.wait(lambda s: s["path"] == str(other), 10, "the overwrite")
    assert json.loads(other.read_text())["name"] == json.loads((ROOT / "scenes" / "arch.json").read_text())["name"]
    assert not st["gl_errors"]
