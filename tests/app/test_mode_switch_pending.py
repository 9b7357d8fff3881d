"""The first switch to a mode whose kernels are not compiled must not freeze the scene.  A real
window under Xvfb: the default scene plays in soft_step; the solver panel's combo picks penalty
(real clicks); while penalty compiles, world time goes on in soft_step, the solver panel shows the
pending switch with its progress, and the mode becomes penalty by itself once compiled, the scene
still running.

The cache is a copy of the suite's warm one without penalty's unit markers, and the compiler
process holds penalty's units (``STELKROPP_HOLD``, app/compile_worker.py) until the test has seen
the pending switch: on a warm cache they would load in seconds (a race with the checks), on a cold
one the test spent minutes compiling every kernel of the scene first.
(Before, the pick set the mode at once and world time stood still, "compiling penalty ...", until
the mode was compiled: the stand-still check after the click fails there.)"""
from __future__ import annotations

import time

import numpy as np
import pytest

from sandbox_pixels import ROOT
from test_progress_once import stripped_cache

pytestmark = [pytest.mark.app, pytest.mark.slow]

COMPILE_TIMEOUT = 300    # the scene's own kernels, from the warm cache, on a loaded 2-core machine
SWITCH_TIMEOUT = 300     # penalty's, once let go (from the warm cache too)
STALL = 20.0             # s of real time the world time may stand still while penalty compiles


def centre(rect):
    x0, y0, x1, y1 = rect
    return int((x0 + x1) / 2), int((y0 + y1) / 2)


def amber_pixels(img, rect) -> int:
    """Pixels of the panels' amber text (app/panels/style.py: AMBER, 255 204 89) in ``rect``."""
    x0, y0, x1, y1 = (int(v) for v in rect)
    a = img[max(0, y0):y1, max(0, x0):x1]
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    return int(np.count_nonzero((r > 190) & (g > 0.65 * r) & (g < 0.92 * r) & (b < 0.6 * r)))


def visible(app, key):
    """Scroll the side panel until the widget ``key`` is inside the window; its status."""
    for _ in range(30):
        st = app.settle()
        y0, y1 = st["ui_rects"][key][1], st["ui_rects"][key][3]
        if y0 > 0 and y1 < st["window"][1] - 10:
            return st
        x = centre(st["ui_rects"]["main_window"])[0]
        app.xdo("mousemove", x, 400)
        app.xdo("click", "5" if y1 >= st["window"][1] - 10 else "4")
    raise AssertionError(f"{key} not scrolled into view: {st['ui_rects'][key]}")


class Clock:
    """World time against real time, sampled at every status read: the longest stand-still."""

    def __init__(self):
        self.last = None          # (real s, world time) when the world time last moved
        self.stall = 0.0
        self.samples = 0

    def see(self, st):
        now = time.monotonic()
        self.samples += 1
        if self.last is None or st["time"] > self.last[1]:
            self.last = (now, st["time"])
        self.stall = max(self.stall, now - self.last[0])
        return self.stall


def test_a_mode_switch_keeps_the_scene_running_while_the_mode_compiles(launch, tmp_path):
    held = tmp_path / "hold-penalty"
    held.touch()
    env = dict(stripped_cache(tmp_path, keep=lambda marker: "penalty" not in marker),
               STELKROPP_HOLD=f"solve:penalty,step:penalty,joints:penalty:{held}")
    app = launch(ROOT / "scenes" / "default.json", env=env)
    st = app.wait(lambda s: s.get("ready"), COMPILE_TIMEOUT, "the kernels of the scene's mode")
    st = app.wait(lambda s: s["steps"] > 30, 120, "the scene to play")
    assert st["solver"] == "soft_step" and st["running"], st["solver"]

    # pick penalty in the solver panel's combo, as a user would
    st = visible(app, "solver_combo")
    app.click(*centre(st["ui_rects"]["solver_combo"]))
    st = app.wait(lambda s: "solver:penalty" in s["ui_rects"], 20, "the combo's list")
    st = app.settle()
    app.click(*centre(st["ui_rects"]["solver:penalty"]))
    t_pick, clock = time.monotonic(), Clock()
    st = app.wait(lambda s: clock.see(s) is not None and (s.get("solver_pending") or s["solver"] != "soft_step"),
                  30, "the pick taken")
    picked = st["solver"], st.get("solver_pending")

    # the scene goes on while penalty compiles (before, world time stood still until it was compiled)
    t0 = st["time"]
    st = app.wait(lambda s: clock.see(s) >= STALL or s["time"] > t0 + 2.0, SWITCH_TIMEOUT,
                  "world time to go on after the pick")
    assert clock.stall < STALL, f"the scene stood still for {clock.stall:.0f} s after the pick"
    assert picked[0] == "soft_step", "the mode switched before its kernels were compiled"
    assert picked[1]["mode"] == "penalty", picked
    assert st["solver"] == "soft_step" and st["solver_pending"], "penalty compiled too soon to see it pending"
    st = app.settle()
    line = st["ui_values"]["solver_pending"]
    assert line.startswith("penalty: compiling") and "soft_step runs until then" in line, line
    assert "%" in line
    rect = st["ui_rects"]["solver_pending"]
    assert 0 <= rect[1] < rect[3] <= st["window"][1] and rect[0] >= 0 and rect[2] <= st["window"][0], rect
    img = app.screenshot("pending")            # look at it: the line, the bar and what it waits for
    assert amber_pixels(img, rect) > 150, "the pending switch is not drawn in the solver panel"
    assert not st["gl_errors"] and not st["fault"]
    print("pending:", st["solver_pending"])

    # let go, it becomes penalty by itself (no more input), and world time never stood still meanwhile
    held.unlink()
    st = app.wait(lambda s: clock.see(s) >= STALL or s["solver"] == "penalty", SWITCH_TIMEOUT,
                  "penalty to be compiled and switched to")
    t_switch = time.monotonic() - t_pick
    assert clock.stall < STALL, f"the scene stood still for {clock.stall:.0f} s while penalty compiled"
    assert st["solver_pending"] is None and "solver_pending" not in st["ui_rects"]
    t1, steps1 = st["time"], st["steps"]
    st = app.wait(lambda s: s["time"] > t1 + 1.0 and s["steps"] > steps1 + 30, 120, "penalty to run")
    assert st["solver"] == "penalty" and st["running"] and not st["fault"] and not st["gl_errors"]
    assert st["compiling_note"] == "", st["compiling_note"]
    app.screenshot("switched")
    print(f"penalty {t_switch:.0f} s after the pick; the longest stand-still of world time meanwhile "
          f"{clock.stall:.1f} s ({clock.samples} status reads)")
