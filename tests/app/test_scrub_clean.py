"""A timeline scrub back past an edit the snapshot undoes (a world setting) leaves the scene as
saved: no "*" in the title; scrubbing forward past the edit shows it unsaved again."""
from __future__ import annotations

import numpy as np
import pytest

from test_text_fields import type_into
from test_timeline_events import pause, scrub_to
from test_tools import tools_scene

pytestmark = pytest.mark.app


def title_pixels(app, st, name) -> int:
    """Bright text in the side panel's title bar ("Stelkropp - tools.json" and its "*")."""
    x0, y0, x1, _ = map(int, st["ui_rects"]["main_window"])
    return int(np.count_nonzero(app.screenshot(name)[y0:y0 + 20, x0:x1].min(axis=2) > 170))


@pytest.mark.slow
def test_scrub_back_past_an_edit_clears_the_unsaved_mark(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st = app.wait_ready(10)
    clean = title_pixels(app, st, "clean")
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    app.wait(lambda s: s["time"] > 1.5, 120, "1.5 s of play")
    st = pause(app)
    type_into(app, st["ui_rects"]["sim:gravity"], "3")        # gravity's x: an edit the snapshots hold
    st = app.wait(lambda s: s["dirty"], 10, "the edit")
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    app.wait(lambda s: s["time"] > st["time"] + 1.0, 120, "1 s more")
    st = pause(app)
    assert st["dirty"]
    dirty = title_pixels(app, st, "dirty")
    assert dirty > clean, (dirty, clean)
    st = scrub_to(app, st, 1.0)
    st = app.wait(lambda s: not s["dirty"], 10, "clean after scrubbing back before the edit")
    st = app.settle()
    assert title_pixels(app, st, "scrubbed_back") == clean, "the title still has its '*'"
    st = scrub_to(app, st, st["timeline"]["range"][1] - 0.05)
    app.wait(lambda s: s["dirty"], 10, "unsaved again after scrubbing forward past the edit")
