"""Issue 15, the timeline: while playing the sandbox keeps a snapshot every 0.25 s of simulated
time; dragging the Simulation section's timeline slider (a real mouse drag) shows the world as
it was then, and Play continues from there.  The expected states come from the same scene
loaded here and stepped headless the same number of steps: the core's snapshots continue
bit-identically, so the positions must be equal, not close.  A topology edit and a reset clear
the timeline."""
from __future__ import annotations

import pytest

from app.scenes import load_world
from test_tools import body, to_screen, tools_scene

pytestmark = pytest.mark.app


class Headless:
    """The scene stepped in this process: positions of each body (by name) after n steps."""

    def __init__(self, path):
        self.world = load_world(path)

    def at(self, steps):
        w = self.world
        assert w.steps <= steps, "asked for a step already passed"
        while w.steps < steps:
            w.step()
        return {b.name: (tuple(b.position), b.angle) for b in w.bodies}


def same_state(st, want):
    for b in st["bodies"]:
        assert (tuple(b["position"]), b["angle"]) == want[b["name"]], (b["name"], st["steps"])


@pytest.mark.slow
def test_timeline_scrub_back_and_play_on(launch, tmp_path):
    path = tools_scene(tmp_path / "tools.json")
    app = launch(path, "--paused")
    ref = Headless(path)
    st = app.wait_ready(10)
    assert st["timeline"]["n"] == 0
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    st = app.wait(lambda s: s["time"] > 3.0, 120, "3 s of play")
    app.key("space")
    st = app.wait(lambda s: not s["running"], 10, "paused")
    st = app.settle()
    dt = st["dt"]
    tl = st["timeline"]
    # one snapshot every 15 steps from t = 0 up to now
    assert tl["range"][0] == 0.0 and tl["n"] == st["steps"] // 15 + 1, tl
    same_state(st, ref.at(st["steps"]))
    t_end = st["time"]
    # drag the slider's grab from its right end (now) to ~1 s
    x0, y0, x1, y1 = st["ui_rects"]["sim:timeline"]
    lo, hi = tl["range"]
    y = (y0 + y1) / 2
    grab = x1 - 6
    target = x0 + (x1 - x0) * (1.0 - lo) / (hi - lo)
    app.drag((grab, y), (target, y), steps=25)
    app.settle()
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: s["timeline"]["cursor"] is not None and abs(s["time"] - 1.0) < 0.6, 20,
                  "the world back at ~1 s")
    st = app.settle()
    assert not st["running"] and st["steps"] % 15 == 0, (st["steps"], st["time"])
    assert st["time"] == pytest.approx(st["steps"] * dt, abs=1e-9)
    shown_steps = st["steps"]
    same_state(st, Headless(path).at(shown_steps))       # the recorded state at that time, bit for bit
    c_then = body(st, "c")["position"]
    app.screenshot("scrubbed")
    # play on: the world continues from there (the later snapshots are dropped)
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    st = app.wait(lambda s: s["steps"] > shown_steps + 40, 60, "play on from the scrubbed moment")
    app.key("space")
    st = app.wait(lambda s: not s["running"], 10, "paused")
    st = app.settle()
    assert st["time"] < t_end and body(st, "c")["position"] != c_then
    tl = st["timeline"]
    assert tl["cursor"] is None and tl["range"][1] <= st["time"] + 1e-9 and tl["n"] == st["steps"] // 15 + 1, tl
    ref2 = Headless(path)
    same_state(st, ref2.at(st["steps"]))
    # a reset clears it
    cleared = tl["cleared"]
    app.key("r")
    st = app.wait(lambda s: s["time"] < 0.2 and s["timeline"]["cleared"] == cleared + 1, 20, "the reset")
    assert st["timeline"]["n"] <= 1
    # deleting a body changes the topology: the timeline is cleared (restore would refuse)
    app.key("space")
    st = app.wait(lambda s: s["timeline"]["n"] >= 3, 60, "new snapshots")
    app.key("space")
    st = app.wait(lambda s: not s["running"], 10, "paused")
    cleared, n = st["timeline"]["cleared"], st["timeline"]["n"]
    # a click on a dynamic body holds a mouse joint until release: no edit, the timeline stays
    app.click(*to_screen(st, body(st, "c")["position"]))
    st = app.wait(lambda s: s["selection"] == [body(s, "c")["id"]] and s["n_tool_joints"] == 0, 10, "c clicked")
    st = app.settle()
    assert st["timeline"]["n"] == n and st["timeline"]["cleared"] == cleared and not st["timeline"]["held"]
    app.click(*to_screen(st, body(st, "a")["position"]))
    st = app.wait(lambda s: s["selection"] == [body(s, "a")["id"]], 10, "a selected")
    app.key("Delete")
    st = app.wait(lambda s: s["n_bodies"] == 3 and s["timeline"]["n"] == 0, 10, "timeline cleared by the delete")
    assert st["timeline"]["cleared"] == cleared + 1 and not st["gl_errors"]
