"""The solver panel's Find settings button (issue 19): the tuner on the open scene in a background
process, its progress and Cancel, the choice applied as one undoable edit.  A real window under
Xvfb, real clicks (xdotool)."""
from __future__ import annotations

import json
import os
import time

import pytest

pytestmark = pytest.mark.app


def box_scene(path):
    """A box sliding on the ground, run at 16 sub-steps: an expensive setting, so a budget of
    1 cm buys a cheaper one (the scene as it is is the tuner's speed baseline)."""
    path.write_text(json.dumps({
        "format": "stelkropp.scene", "version": 1, "name": "box",
        "world": {"gravity": [0, -10], "solver": "soft_step", "settings": {"substeps": 16}},
        "bodies": [{"name": "ground", "kind": "static", "shape": {"box": [16, 1]}, "position": [0, -0.5]},
                   {"name": "box", "shape": {"box": [1.2, 1.2]}, "position": [0, 0.6], "velocity": [2, 0]}]}))
    return path


def centre(rect):
    x0, y0, x1, y1 = rect
    return int((x0 + x1) / 2), int((y0 + y1) / 2)


def reach(app, key, timeout=10):
    """Scroll the side panel (wheel over it) until the widget ``key`` is on screen; its status."""
    st = app.wait(lambda s: key in s["ui_rects"], timeout, key)
    for _ in range(15):
        y0, y1 = st["ui_rects"][key][1], st["ui_rects"][key][3]
        if 30 < y0 and y1 < 770:
            return st
        app.xdo("mousemove", 150, 500, "click", "5" if y1 >= 770 else "4")
        st = app.settle()
    raise AssertionError(f"{key} not scrolled into view: {st['ui_rects'][key]}")


def press(app, key):
    st = reach(app, key)
    app.click(*centre(st["ui_rects"][key]))
    return app.settle()


def gone(pid, seconds) -> bool:
    """Whether process ``pid`` exits (and is reaped by the sandbox) within ``seconds``; the
    worker says "cancelled" just before its interpreter shuts down, which takes a moment."""
    t0 = time.monotonic()
    while time.monotonic() - t0 < seconds:
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return True
        time.sleep(0.1)
    return False


def find(st):
    return st["ui_values"].get("find", {})


@pytest.mark.slow
def test_find_settings_apply_and_undo(launch, tmp_path):
    app = launch(box_scene(tmp_path / "box.json"), "--paused")
    st = app.wait_ready(20)
    before = st["ui_values"]["solver_settings"]
    assert before["settings"]["substeps"] == 16
    t0 = time.monotonic()
    press(app, "find:start")
    st = app.wait(lambda s: find(s).get("state") == "running" and find(s)["progress"][2] > 0, 30,
                  "the search's progress")
    app.screenshot("find_running")
    # on a cold cache the worker compiles every mode's kernels before its first runs finish (a
    # clean clone under load: 20 kernels in the first 50 s; 53 kernels and round 1 at 25 of 30
    # after 240 s on a loaded clean clone), so the end gets minutes, not seconds
    seen = []     # statuses while the search's process compiled (a cold cache): the label must show

    def ended(s):
        if find(s).get("compiling"):
            seen.append(("find:compiling" in s["ui_rects"], find(s)["compiled"]))
        return find(s).get("state") not in ("running", "cancelling")

    st = app.wait(ended, 600, "the search's end")
    took = time.monotonic() - t0
    # on a warm cache nothing compiles and ``seen`` stays empty; on a cold one (a clean clone)
    # the label was on screen while it did (a status is written between frames, and "compiling"
    # lingers COMPILE_GAP s after a kernel, so a status and its frame may disagree at an edge)
    assert not seen or any(shown for shown, _ in seen), seen
    print(f"compiling seen in {len(seen)} statuses, label drawn in {sum(s for s, _ in seen)}")
    f = find(st)
    assert f["state"] == "done", f
    res, choice = f["result"], f["result"]["choice"]
    assert choice is not None, res
    assert res["budget"] == 0.01 and res["metric"] == "trajectory" and res["steps"] <= 120
    assert choice["error"] <= 0.01 and choice["seconds"] < res["baseline"]["seconds"], res
    want = {k: choice[k] for k in ("solver", "settings", "integrator", "dt")}
    assert want != before                  # something to apply (16 sub-steps are never the fastest)
    st = reach(app, "find:apply")
    app.screenshot("find_done")
    app.click(*centre(st["ui_rects"]["find:apply"]))
    st = app.wait(lambda s: s["ui_values"]["solver_settings"] == want, 10, "the choice applied")
    assert st["solver"] == choice["solver"] and st["dt"] == pytest.approx(choice["dt"])
    assert find(st)["applied"] and any("applied" in m for m in st["messages"])
    app.xdo("mousemove", 800, 400)          # Ctrl+Z over the scene, not a text field
    app.settle()
    app.key("ctrl+z")
    st = app.wait(lambda s: s["ui_values"]["solver_settings"] == before, 10, "the undo")
    assert not st["gl_errors"] and not st["fault"]
    print(f"search + apply: {took:.1f} s, {res['candidates']} candidates, choice {choice['key']}")


@pytest.mark.slow
def test_find_settings_cancel_and_a_refusal(launch, tmp_path):
    app = launch(box_scene(tmp_path / "box.json"), "--paused")
    st = app.wait_ready(20)
    before = st["ui_values"]["solver_settings"]
    st = press(app, "find:steps")          # a long search: it must not end before Cancel
    app.key("ctrl+a")
    app.xdo("type", "3000")
    app.key("Return")
    app.wait(lambda s: find(s)["options"]["steps"] == 3000, 10, "the steps field")
    press(app, "find:start")
    # round 1 is reported once the worker has measured its first candidate: on a cold cache that
    # waits for its kernels (see the apply test above), so minutes, not seconds
    st = app.wait(lambda s: find(s).get("state") == "running" and find(s)["progress"][0] == "round 1",
                  240, "round one under way")
    pid = find(st)["pid"]
    assert find(st)["progress"][1] < find(st)["progress"][2]
    press(app, "find:cancel")
    st = app.wait(lambda s: find(s).get("state") == "cancelled", 15, "the search to stop")
    assert gone(pid, 5.0), "the tuner process still runs 5 s after the search said it stopped"
    st = app.frames(5)
    assert st["ui_values"]["solver_settings"] == before and find(st)["result"] is None
    assert any("cancelled" in m for m in st["messages"])
    # a metric the scene cannot be measured by (no springs or joints): a notice, the app runs on
    press(app, "find:metric")
    press(app, "find:metric:constraint")
    press(app, "find:start")
    st = app.wait(lambda s: find(s).get("state") == "error", 30, "the refusal")
    assert "springs and joints" in find(st)["error"]
    assert any("find settings" in m and "constraint" in m for m in st["messages"])
    app.screenshot("find_refused")
    st = app.frames(10)
    assert st["ui_values"]["solver_settings"] == before and not st["gl_errors"]
