"""Ctrl+Q quits the sandbox (asking first about unsaved edits, as the window's close button)."""
from __future__ import annotations

import time

import pytest

from test_saving import centre, scene_point
from test_tools import tools_scene

pytestmark = pytest.mark.app


def test_ctrl_q_asks_about_edits_then_quits(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st = app.wait_ready(10)
    n0 = st["n_bodies"]
    app.key("2")                                          # the box tool: one new box is an edit
    app.click(*scene_point(st))
    st = app.wait(lambda s: s["n_bodies"] == n0 + 1 and s["dirty"], 10, "a new box")
    app.key("ctrl+q")
    app.wait(lambda s: s["dialog"] == "Unsaved edits", 10, "the question about the edits")
    st = app.settle()
    assert app.proc.poll() is None
    app.click(*centre(st["ui_rects"]["dialog:Cancel"]))
    app.wait(lambda s: s["dialog"] is None, 10, "the question cancelled")
    app.xdo("mousemove", *scene_point(st))
    app.settle()
    app.key("ctrl+z")
    app.wait(lambda s: not s["dirty"] and s["dialog"] is None, 10, "the edit undone")
    app.key("ctrl+q")
    t0 = time.monotonic()
    while app.proc.poll() is None and time.monotonic() - t0 < 20:
        time.sleep(0.1)
    assert app.proc.returncode == 0, f"Ctrl+Q did not quit (returncode {app.proc.returncode})"
