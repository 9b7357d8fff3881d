"""A refused field edit's message belongs to the scene it was made in: opening another scene
clears it (it stayed under the gravity field before)."""
from __future__ import annotations

import pytest

from sandbox_pixels import ROOT, red_text_pixels
from test_saving import centre, scene_point
from test_text_fields import type_into

pytestmark = pytest.mark.app


def open_from_list(app, path):
    """Double-click ``path`` in the Scene section's list (Ctrl+Shift+S opens the section)."""
    app.xdo("mousemove", *scene_point(app.status()))
    app.settle()
    app.key("ctrl+shift+s")
    app.settle()
    app.key("Escape")
    st = app.wait(lambda s: f"scene:{path}" in s["ui_rects"], 10, f"{path.name} in the scene list")
    app.xdo("mousemove", *centre(st["ui_rects"][f"scene:{path}"]))
    app.settle()
    app.xdo("click", "--repeat", "2", "--delay", "80", "1")
    return app.wait(lambda s: s["path"] == str(path) or s["dialog"], 20, f"{path.name} to open")


def test_a_refusal_is_cleared_by_opening_another_scene(launch):
    app = launch(ROOT / "scenes" / "arch.json", "--paused")
    st = app.wait_ready(10)
    type_into(app, st["ui_rects"]["sim:gravity"], "1e999")
    st = app.wait(lambda s: "1000" in s["edit_error"] and "refusal" in s["ui_rects"], 10, "the refusal")
    st = app.settle()
    x0, y0, x1, y1 = map(int, st["ui_rects"]["refusal"])
    beside = (x0, y0, x1, y1)
    assert red_text_pixels(app.screenshot("refused"), *beside) > 20, "the refusal is not shown beside the field"
    st = open_from_list(app, ROOT / "scenes" / "car.json")
    assert st["dialog"] is None and st["path"].endswith("car.json"), st["dialog"]
    st = app.settle()
    assert st["edit_error"] == ""
    assert "refusal" not in st["ui_rects"]
    assert red_text_pixels(app.screenshot("other_scene"), *beside) == 0, "the old refusal is still shown"
