"""A scene opened while the launch's kernels compile, in another solver mode, waits for that mode
too, and the note above the scene says so: it names and counts the mode's units beside the
launch's, stays (with its bar, Play saying it waits) after the launch's units are in, until the
scene steps, and only then goes.  (It named only the launch scene's solver, then gave way to a
bare "compiling penalty ..." line while Play showed Pause over a scene that did not move.)

The cache is a copy of the warm one with every unit marker gone (the launch's units load from
numba's cache in seconds) and the soft_step and penalty solvers' kernels deleted (they compile
for real, so the launch is still compiling when the scene is opened, and the wait after the
launch's units lasts)."""
from __future__ import annotations

import json

import pytest

from sandbox_pixels import ROOT
from test_progress_once import bar_bands, stripped_cache
from test_saving import centre

pytestmark = [pytest.mark.app, pytest.mark.slow]


def penalty_scene(folder):
    """The pyramid in penalty mode, in the user's scene folder (listed first in the Scene section)."""
    data = json.loads((ROOT / "scenes" / "pyramid.json").read_text())
    data["world"].update(solver="penalty", settings={})
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "pyramid_penalty.json"
    path.write_text(json.dumps(data))
    return path


def open_from_list(app, path):
    """Double-click ``path``'s row in the Scene section's list (real clicks)."""
    x0, y0, x1, y1 = app.status()["free_rect"]
    app.xdo("mousemove", int(x0 + 300), int(y1 - 40))
    app.settle()
    app.key("ctrl+shift+s")                 # opens the Scene section
    app.settle()
    app.key("Escape")
    st = app.wait(lambda s: f"scene:{path}" in s["ui_rects"], 20, "the user's scenes listed")
    for attempt in range(3):  # a person double-clicks again when the first one did not take
        x, y = centre(app.status()["ui_rects"][f"scene:{path}"])
        app.xdo("mousemove", x, y)
        app.settle()
        app.xdo("click", "--repeat", "2", "--delay", "80", "1")
        try:
            return app.wait(lambda s: s["path"] == str(path), 10, f"{path.name} open")
        except AssertionError:
            if attempt == 2:
                raise


def test_a_scene_opened_mid_compile_in_another_mode_is_waited_for_in_words(launch, tmp_path):
    env = stripped_cache(tmp_path)
    # penalty's own kernels compile for real (numba keeps each module's in a folder of its own)
    # and so do soft_step's, so the launch is still compiling when the other scene is opened
    gone = [f for f in (tmp_path / "cache").glob("numba/*/*/penalty*")]
    gone += [f for f in (tmp_path / "cache").glob("numba/*/soft_step_*/*")]
    assert gone, "no penalty kernels in the cache to delete"
    for f in gone:
        f.unlink()
    scene = penalty_scene(tmp_path / "data" / "stelkropp" / "scenes")
    app = launch(ROOT / "scenes" / "default.json", env=env)
    app.wait(lambda s: "main_window" in s.get("ui_rects", {}), 30, "the panels")
    st = open_from_list(app, scene)
    assert not st["ready"], "the scene must be opened while the launch's units load"
    st = app.frames(4)
    assert "the penalty solver" in st["ui_values"]["progress"], st["ui_values"]["progress"]

    # the launch's units are in: the note stays, with its bar, until penalty's are
    st = app.wait(lambda s: s["ready"], 300, "the launch's units")
    st = app.frames(4)
    assert st["steps"] == 0, "penalty cannot be compiled this soon"
    assert "progress" in st["ui_rects"] and st["ui_values"]["play_state"] == "waiting", st["ui_values"]
    assert "penalty" in st["ui_values"]["progress"] and "kernels left" in st["ui_values"]["progress"]
    img = app.screenshot("waiting_for_penalty")
    x0, y0, x1, y1 = st["ui_rects"]["progress"]
    assert bar_bands(img, x0 + 8, y0, x1 - 8, y1) == 1, "the note above the scene has its bar"

    st = app.wait(lambda s: s["steps"] > 0, 900, "the penalty scene to step")
    st = app.frames(4)
    assert st["solver"] == "penalty" and st["ui_values"]["play_state"] == "running"
    assert "progress" not in st["ui_rects"] and not st["warm_errors"]
