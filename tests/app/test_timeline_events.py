"""A drag, a throw and a property edit are events on the timeline, not reasons to drop it: a
thrown body can be rewound to before the throw.  Single steps (S) from a scrubbed moment drop the
old future, as Play does."""
from __future__ import annotations

import pytest

from sandbox_pixels import body_pixels
from test_text_fields import type_into
from test_timeline import Headless, same_state
from test_tools import body, to_screen, tools_scene

pytestmark = pytest.mark.app


def scrub_to(app, st, t):
    """Drag the timeline slider's grab from its right end to time ``t``; returns the status."""
    x0, y0, x1, y1 = st["ui_rects"]["sim:timeline"]
    lo, hi = st["timeline"]["range"]
    hi = max(hi, st["time"])
    y = (y0 + y1) / 2
    app.drag((x1 - 6, y), (x0 + (x1 - x0) * (t - lo) / (hi - lo), y), steps=25)
    app.settle()
    app.xdo("mouseup", 1)
    return app.wait(lambda s: s["timeline"]["cursor"] is not None and abs(s["time"] - t) < 0.6, 20,
                    f"the world back at ~{t} s")


def pause(app):
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    app.wait(lambda s: not s["running"], 10, "paused")
    return app.settle()


@pytest.mark.slow
def test_a_throw_stays_on_the_timeline_and_can_be_rewound(launch, tmp_path):
    path = tools_scene(tmp_path / "tools.json")
    app = launch(path, "--paused")
    st = app.wait_ready(10)
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    st = app.wait(lambda s: s["time"] > 1.5, 120, "1.5 s of play")
    cleared = st["timeline"]["cleared"]
    # throw box a up and to the right while the scene plays
    a0 = body(st, "a")["position"]
    x, y = to_screen(st, a0)
    app.drag((x, y), (x + 120, y - 160), steps=8)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: s["n_tool_joints"] == 0 and body(s, "a")["position"][1] > 1.5, 20, "the throw")
    st = app.wait(lambda s: s["time"] > st["time"] + 1.0, 60, "1 s after the throw")
    st = pause(app)
    tl = st["timeline"]
    assert tl["cleared"] == cleared, "the drag cleared the timeline"
    assert tl["range"][0] == 0.0 and tl["range"][1] > st["time"] - 0.3, tl
    # rewind to 1 s, before the throw: box a stands where it stood, as the scene ran untouched
    st = scrub_to(app, st, 1.0)
    st = app.settle()
    same_state(st, Headless(path).at(st["steps"]))
    assert body(st, "a")["position"][1] == pytest.approx(0.6, abs=0.02)
    app.key("Escape")                    # deselected: drawn in its own colour
    st = app.settle()
    img = app.screenshot("rewound_before_the_throw")
    x, y = map(int, to_screen(st, body(st, "a")["position"]))
    assert body_pixels(img, x - 8, x + 8, y - 8, y + 8, static=False) > 150, "box a is not drawn back"
    # a property edit (gravity's x) keeps the timeline too
    type_into(app, st["ui_rects"]["sim:gravity"], "3")
    st = app.wait(lambda s: s["dirty"], 10, "the edit")
    st = app.settle()
    assert st["timeline"]["cleared"] == cleared and st["timeline"]["n"] == tl["n"]


@pytest.mark.slow
def test_single_steps_from_the_past_drop_the_old_future(launch, tmp_path):
    path = tools_scene(tmp_path / "tools.json")
    app = launch(path, "--paused")
    app.wait_ready(10)
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    app.wait(lambda s: s["time"] > 3.0, 120, "3 s of play")
    st = pause(app)
    st = scrub_to(app, st, 1.0)
    shown = st["steps"]
    app.xdo("mousemove", 700, 150)
    app.settle()
    for _ in range(30):
        app.key("s")
    st = app.wait(lambda s: s["steps"] == shown + 30, 30, "30 single steps")
    tl = st["timeline"]
    assert tl["cursor"] is None and tl["range"][1] <= st["time"] + 1e-9, f"the old future is kept: {tl}"
    # the slider's right end is now: dragging it there shows this run, not the old one
    assert st["ui_values"]["timeline"] == pytest.approx(st["time"])
