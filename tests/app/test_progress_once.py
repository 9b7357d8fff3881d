"""The compile progress is shown once, in honest words: while the kernels load, the note above the
scene has the one progress bar (the Simulation section says only that Play waits, in one line, so
its fields do not jump up under the pointer once the kernels are in); "first launch only" is said
only when nothing is in the cache yet, not on a later launch that compiles what a scene adds.

Both launches use a copy of the warm kernel cache with unit markers removed: the window then
waits for those units as on a cold launch (each loads from numba's cache in seconds, instead of
compiling for minutes; tests/app/test_first_launch.py is the cold launch itself)."""
from __future__ import annotations

import shutil

import numpy as np
import pytest

from physics.compile_units import cache_dir
from sandbox_pixels import ROOT

pytestmark = [pytest.mark.app, pytest.mark.slow]

FRAME_BG = np.array([33, 38, 51])      # a field's and a progress bar's frame (app/panels/style.py)


def stripped_cache(tmp_path, keep=lambda marker: False):
    """A copy of the warm cache whose unit markers are gone except those ``keep`` keeps; the env
    that points a sandbox at it."""
    # the cache the suite compiled into, for this version of physics/ only: a user's (or CI's)
    # cache also keeps older versions' folders, whose markers name other kernels
    here = cache_dir()
    assert here is not None and any(here.glob("unit-*.ok")), f"no compiled units in {here}"
    numba_dir = tmp_path / "cache" / "numba" / here.name
    shutil.copytree(here, numba_dir, ignore=shutil.ignore_patterns("*.lock"))
    for m in numba_dir.glob("unit-*.ok"):
        if not keep(m.name):
            m.unlink()
    return {"STELKROPP_CACHE_DIR": str(tmp_path / "cache"), "NUMBA_CACHE_DIR": str(numba_dir)}


def bar_bands(img, x0, y0, x1, y1) -> int:
    """How many bands of rows in the rectangle are a progress bar: a frame, filled (yellow) or not,
    at least 85 % as wide as the rectangle (a number field's frame leaves room for its label; a
    bar spans the width)."""
    area = img[int(y0):int(y1), int(x0):int(x1)]
    frame = np.all(np.abs(area - FRAME_BG) <= 2, axis=-1)
    fill = (area[..., 0] > 200) & (area[..., 1] > 150) & (area[..., 2] < 80)
    rows = np.mean(frame | fill, axis=1) >= 0.85
    return int(np.count_nonzero(rows[1:] & ~rows[:-1]) + rows[0])


def test_one_bar_and_the_fields_stay_put(launch, tmp_path):
    app = launch(ROOT / "scenes" / "default.json", env=stripped_cache(tmp_path))
    st = app.wait(lambda s: "main_window" in s.get("ui_rects", {}) and "progress" in s["ui_rects"], 30,
                  "the panels and the progress note")
    img = app.screenshot("loading")
    st = app.status()
    assert not st["ready"], "the screenshot must be taken while the kernels load"
    px0, py0, px1, py1 = st["ui_rects"]["progress"]
    assert bar_bands(img, px0 + 8, py0, px1 - 8, py1) == 1, "the note above the scene has its bar"
    mx0, _, mx1, _ = st["ui_rects"]["main_window"]
    top = st["ui_rects"]["section:Simulation"][3]
    field = st["ui_rects"]["sim:time_scale"]
    assert bar_bands(img, mx0 + 10, top, mx1 - 24, field[1]) == 0, "a second bar in the Simulation section"
    assert st["ui_values"]["play_state"] == "waiting"
    assert st["ui_values"]["progress_head"].startswith("Compiling the physics kernels (first launch only)")
    # once the kernels are in, the fields are where they were (one line up at most)
    st = app.wait(lambda s: s["ready"], 300, "the kernels loaded")
    st = app.frames(4)
    assert abs(st["ui_rects"]["sim:time_scale"][1] - field[1]) <= 20, (field, st["ui_rects"]["sim:time_scale"])
    assert "progress" not in st["ui_rects"] and "progress" not in st["ui_values"]


def test_a_later_launch_does_not_say_first_launch(launch, tmp_path):
    # an earlier launch compiled penalty's joint stage, nothing this scene needs
    env = stripped_cache(tmp_path, keep=lambda m: "joints-penalty" in m)
    app = launch(ROOT / "scenes" / "default.json", env=env)
    st = app.wait(lambda s: not s["ready"] and "progress_head" in s.get("ui_values", {}), 30,
                  "the progress note")
    head = st["ui_values"]["progress_head"]
    assert "first launch" not in head and "this scene needs" in head, head
    assert "waiting for the soft_step solver" in st["ui_values"]["progress"], st["ui_values"]["progress"]
    app.screenshot("later_launch")
    app.wait(lambda s: s["ready"], 300, "the kernels loaded")
