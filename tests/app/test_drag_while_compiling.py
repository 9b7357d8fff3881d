"""A drag while the open mode's joint stage still compiles says what it waits for: the mouse drag
is a joint, so the step waits for that stage (compiled after the scene's own units on a first
launch, minutes cold).  "Dragging did nothing while 'compiling the joints' showed": now the
progress note above the scene comes back for it, counting and naming the joint stage, Play says
it waits, and once the body is let go the scene steps again at once.

The cache is a copy of the suite's warm one without the joint stages' unit markers, and the compiler process
holds the joint stage (``STELKROPP_HOLD``, app/compile_worker.py) until the test lets it go: on a
warm cache the stage would load in seconds, a race with the drag; on a cold one it takes minutes of
the window worker's time.  Let go, the stage loads and the same drag moves the body."""
from __future__ import annotations

import pytest

from test_progress_once import bar_bands, stripped_cache
from test_text_fields import fields_scene
from test_tools import body

pytestmark = [pytest.mark.app, pytest.mark.slow]


def test_a_drag_waiting_for_the_joint_stage_says_so(launch, tmp_path):
    held = tmp_path / "hold-the-joints"
    held.touch()
    env = dict(stripped_cache(tmp_path, keep=lambda marker: "joints" not in marker), STELKROPP_HOLD=f"joints:{held}")
    app = launch(fields_scene(tmp_path / "fields.json"), env=env)
    st = app.wait_ready(10, joints=False)
    assert not st["joints_ready"], "the joint stage loaded while held"
    assert "progress" not in st["ui_rects"] and st["ui_values"]["play_state"] == "running"
    b = body(st, "b")
    x, y = b["screen"]
    app.drag((x, y), (x + 60, y - 80), steps=10)
    st = app.wait(lambda s: s["n_tool_joints"] == 1 and "progress" in s["ui_rects"], 20, "the drag's wait said")
    assert not st["joints_ready"], "the joint stage compiled before the drag's wait was seen"
    assert st["ui_values"]["play_state"] == "waiting"
    assert "the joints of soft_step" in st["ui_values"]["progress"], st["ui_values"]["progress"]
    img = app.screenshot("drag_waits_for_the_joints")
    x0, y0, x1, y1 = st["ui_rects"]["progress"]
    assert bar_bands(img, x0 + 8, y0, x1 - 8, y1) == 1, "the note above the scene has its bar"
    steps = st["steps"]
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: s["n_tool_joints"] == 0 and s["steps"] > steps + 10, 30, "the scene stepping again")
    assert "progress" not in st["ui_rects"] and st["ui_values"]["play_state"] == "running"

    # the stage let go: it loads, and the same drag now moves the body with no note
    held.unlink()
    st = app.wait(lambda s: s["joints_ready"], 120, "the joint stage loaded")
    b = body(st, "b")
    x, y = b["screen"]
    app.drag((x, y), (x + 60, y - 80), steps=10)
    st = app.wait(lambda s: s["n_tool_joints"] == 1 and body(s, "b")["position"][1] > b["position"][1] + 0.5,
                  20, "the dragged body lifted")
    assert "progress" not in st["ui_rects"] and st["ui_values"]["play_state"] == "running"
    app.xdo("mouseup", 1)
