"""A picked laser emitter is read out in the inspector (its beam's length to the last surface it
meets, its bounces, the bodies it hits) and can be moved, not only re-aimed: Ctrl+drag in the
scene, or its point typed in the inspector; both undoable.  The expected beam comes from the
scene's box faces (test_lasers' plane intersections), not from the core's ray cast."""
from __future__ import annotations

import math

import numpy as np
import pytest

from test_compare import centre
from test_lasers import expected_beam, red
from test_text_fields import type_into
from test_tools import body, to_screen, tools_scene

pytestmark = pytest.mark.app


def text_pixels(img, rect) -> int:
    """Light text pixels (imgui's text colour) inside ``rect``."""
    x0, y0, x1, y1 = map(int, rect)
    a = img[y0:y1, x0:x1]
    return int(np.count_nonzero(a.min(axis=2) > 170))


@pytest.mark.slow
def test_laser_readout_and_moving_the_emitter(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st = app.wait_ready(10)
    app.click(*centre(st["ui_rects"]["tool:laser"]))
    st = app.wait(lambda s: s["tool"] == "laser", 10, "the laser tool")
    app.drag(to_screen(st, (-7.0, 3.0)), to_screen(st, (-6.0, 2.0)))     # down-right at box a
    app.settle()  # the last move handled before the release (a loaded machine merges them)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: len(s["lasers"]) == 1 and "inspector:laser" in s["ui_values"], 10, "the readout")
    st = app.settle()
    lz, out = st["lasers"][0], st["ui_values"]["inspector:laser"]
    want, _ = expected_beam(st, lz["local"], lz["angle"])
    assert len(want) >= 3, "the aim should meet box a, then the ground"
    length = float(np.sum(np.linalg.norm(np.diff(want, axis=0), axis=1)))
    assert out["length"] == pytest.approx(length, abs=1e-6)
    assert out["bounces"] == len(want) - 1          # every hit mirrors the beam; the last leaves
    assert out["hits"][:2] == [body(st, "a")["id"], body(st, "ground")["id"]], out
    assert out["lines"][0] == f"beam {length:.3f} m to its last hit, {len(want) - 1} bounces"
    assert out["lines"][1].startswith("hits a, then ground"), out["lines"]
    img = app.screenshot("laser_readout")
    assert text_pixels(img, st["ui_rects"]["inspector:laser:readout"]) > 100, "the readout is not drawn"
    # Ctrl+drag the emitter up 2 m: it moves (fixed in the world still), pointing the same way
    app.xdo("keydown", "ctrl")
    app.drag(to_screen(st, (-7.0, 3.0)), to_screen(st, (-7.0, 5.0)))
    app.settle()  # the last move handled before the release (a loaded machine merges them)
    app.xdo("mouseup", 1)
    app.xdo("keyup", "ctrl")
    st = app.wait(lambda s: s["lasers"][0]["local"][1] > 4.5, 10, "the emitter moved")
    st = app.settle()
    moved = st["lasers"][0]
    assert moved["body"] is None and moved["local"] == pytest.approx((-7.0, 5.0), abs=0.05)
    assert moved["angle"] == pytest.approx(lz["angle"], abs=1e-9)
    assert moved["path"][0] == pytest.approx(moved["local"], abs=1e-9)
    assert st["ui_values"]["inspector:laser"]["length"] != pytest.approx(length, abs=1e-3)
    img = app.screenshot("laser_moved")
    a, b = np.array(moved["path"][0]), np.array(moved["path"][1])
    assert red(img, *to_screen(st, (a + b) / 2)) > 3, "no beam drawn from the moved emitter"
    # dropped on box c it rides with c
    app.xdo("keydown", "ctrl")
    app.drag(to_screen(st, (-7.0, 5.0)), to_screen(st, (0.2, 3.1)))
    app.settle()  # the last move handled before the release (a loaded machine merges them)
    app.xdo("mouseup", 1)
    app.xdo("keyup", "ctrl")
    st = app.wait(lambda s: s["lasers"][0]["body"] == body(s, "c")["id"], 10, "the emitter on c")
    assert st["lasers"][0]["local"] == pytest.approx((0.2, 0.1), abs=0.05)
    # undo twice: back where it was placed
    app.xdo("mousemove", 700, 150)
    app.key("ctrl+z")
    st = app.wait(lambda s: s["lasers"][0]["body"] is None, 10, "undo of the move onto c")
    app.key("ctrl+z")
    st = app.wait(lambda s: s["lasers"][0]["local"] == pytest.approx((-7.0, 3.0), abs=0.05), 10, "undo of the move")
    # the inspector's point field moves it too
    app.click(*to_screen(st, (-7.0, 3.0)))
    st = app.wait(lambda s: "inspector:laser:point" in s["ui_rects"], 10, "the emitter picked")
    st = app.settle()
    type_into(app, st["ui_rects"]["inspector:laser:point"], "6.5")
    st = app.wait(lambda s: s["lasers"][0]["local"][0] == pytest.approx(6.5, abs=1e-6), 10, "moved by the field")
    assert st["lasers"][0]["local"][1] == pytest.approx(3.0, abs=0.05) and not st["gl_errors"]
