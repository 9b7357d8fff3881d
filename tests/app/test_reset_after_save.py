"""Reset on a shipped scene with unsaved edits, answered "Save, then continue": the edits are saved
to the user's folder, and the reset goes back to the scene as it was loaded, not to that copy."""
from __future__ import annotations

import json

import pytest

from sandbox_pixels import ROOT, body_pixels
from test_saving import centre

pytestmark = pytest.mark.app


def test_reset_after_save_then_continue_goes_back_to_the_loaded_scene(launch):
    shipped = ROOT / "scenes" / "arch.json"
    app = launch(shipped, "--paused")
    st0 = app.wait_ready(20)
    n0 = st0["n_bodies"]
    x, y = int(st0["free_rect"][0]) + 80, int(st0["free_rect"][1]) + 60    # the empty sky left of the arch
    app.key("2")                                     # the box tool
    app.click(x, y)
    st = app.wait(lambda s: s["n_bodies"] == n0 + 1 and s["dirty"], 10, "a new box")
    app.key("r")
    st = app.wait(lambda s: s["dialog"] == "Unsaved edits", 10, "the question about the edits")
    st = app.settle()
    app.click(*centre(st["ui_rects"]["dialog:Save, then continue"]))
    mine = app.user_scenes / "arch.json"
    st = app.wait(lambda s: s["dialog"] is None and mine.exists() and s["time"] == 0.0, 20, "the save and reset")
    st = app.settle()
    assert len(json.loads(mine.read_text())["bodies"]) == n0 + 1, "the edit was not saved"
    assert st["n_bodies"] == n0, "the reset went to the saved copy, not the loaded scene"
    assert st["path"] == str(shipped) and not st["dirty"], (st["path"], st["dirty"])
    img = app.screenshot("reset_to_loaded")
    assert body_pixels(img, x - 12, x + 12, y - 12, y + 12, static=False) == 0, "the new box is still drawn"
