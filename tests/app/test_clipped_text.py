"""Text stays inside the window and its panel: a hint at the right edge is placed to the left of
its point (it was cut off: "no body her"), a failed load's long lines wrap inside their dialog,
and the Compare panel's help wraps inside the side panel."""
from __future__ import annotations

import json

import pytest

from sandbox_pixels import red_text_pixels
from test_compare import centre
from test_newcomer import hint_pixels
from test_tools import tools_scene

pytestmark = pytest.mark.app

W, H = 1280, 800


def test_hint_error_lines_and_panel_help_stay_inside(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st = app.wait_ready(10)
    # two polygon points at the right edge, then Enter: refused, said at the last point
    app.key("3")
    app.settle()
    for p in ((1236, 150), (1262, 190)):
        app.click(*p)
    app.key("Return")
    st = app.wait(lambda s: s["hint"] and "at least 3 points" in s["hint"], 10, "the refusal")
    st = app.settle()
    x0, y0, x1, y1 = st["ui_rects"]["hint"]
    assert 0 <= x0 and x1 <= W and 0 <= y0 and y1 <= H, ("the hint runs off the window", st["ui_rects"]["hint"])
    assert x1 <= 1262, "the hint is not left of its point"
    assert hint_pixels(app.screenshot("hint_right_edge"), st["ui_rects"]["hint"]) > 60, "the hint is not drawn"
    app.key("Escape")
    # a scene file in a deep folder that fails to load: its lines name the long path, and wrap
    deep = tmp_path / ("a_folder_with_a_rather_long_name_" * 3) / ("and_another_one_" * 3)
    deep.mkdir(parents=True)
    bad = deep / "a_scene_file_whose_name_is_long_as_well.json"
    bad.write_text(json.dumps({"format": "stelkropp.scene", "version": 1, "bodies": [{"shape": {"box": [-1, 2]}}]}))
    app.send("on_file_drop", 640, 400, [str(bad)])
    st = app.wait(lambda s: s["scene_errors"], 20, "the scene error")
    st = app.settle()
    assert any(len(line) > 120 for line in st["scene_errors"]), st["scene_errors"]
    x0, y0, x1, y1 = map(int, st["ui_rects"]["scene_errors"])
    assert 0 <= x0 and x1 <= W and 0 <= y0 and y1 <= H and x1 - x0 <= 600, st["ui_rects"]["scene_errors"]
    lines = st["ui_rects"]["scene_errors:lines"]
    assert lines[2] <= x1 - 4, ("the error lines run past the dialog", lines, st["ui_rects"]["scene_errors"])
    assert red_text_pixels(app.screenshot("long_error"), x0, y0, x1, y1) > 100, "the error is not shown"
    # the Compare section's help wraps inside the side panel
    app.click(*centre(st["ui_rects"]["section:Compare solvers"]))
    st = app.wait(lambda s: "compare:help" in s["ui_rects"], 10, "the Compare section open")
    st = app.settle()
    panel, text = st["ui_rects"]["main_window"], st["ui_rects"]["compare:help"]
    assert text[2] <= panel[2] - 8, ("the Compare help runs past the panel", text, panel)
    assert text[3] - text[1] > 20, "the Compare help is on one line: it cannot fit"
