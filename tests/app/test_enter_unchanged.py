"""Enter in a number field that changes nothing is not an edit: a field left as it was, or emptied
(imgui then keeps the old value, and shows it again), leaves the scene unmarked and adds no undo
step, and a value shown rounded is not set to its rounding by Enter alone.  (Each such Enter
marked the scene edited, so opening another one asked about unsaved edits that did not exist.)
A real change still counts, and one undo takes it back."""
from __future__ import annotations

import numpy as np
import pytest

from test_text_fields import fields_scene
from test_tools import body

pytestmark = [pytest.mark.app, pytest.mark.slow]


def enter(app, rect, clear=False):
    """Click the field, optionally select all and delete it, then press Return (real keys)."""
    x0, y0, x1, y1 = rect
    app.click(int(x0 + 30), int((y0 + y1) / 2))
    app.settle()
    app.key("End")
    app.settle()
    if clear:
        app.xdo("keydown", "ctrl")
        app.settle()
        app.key("a")
        app.settle()
        app.xdo("keyup", "ctrl")
        app.key("BackSpace")
        app.settle()
    app.key("Return")
    return app.settle()


def crop(img, rect):
    x0, y0, x1, y1 = (int(v) for v in rect)
    return img[y0 + 2:y1 - 2, x0 + 2:x1 - 2]


def test_enter_without_a_change_is_no_edit(launch, tmp_path):
    app = launch(fields_scene(tmp_path / "fields.json"), "--paused")
    st = app.wait_ready(10)
    rate, dt = st["ui_rects"]["sim:step_rate"], st["dt"]
    before = crop(app.screenshot("before"), rate)
    st = enter(app, rate)
    assert not st["dirty"], "Enter on the step rate as it was marked the scene edited"
    st = enter(app, rate, clear=True)
    st = app.settle()
    assert st["dt"] == dt and not st["dirty"] and st["edit_error"] == "", (st["dt"], st["dirty"], st["edit_error"])
    after = crop(app.screenshot("emptied_rate"), rate)
    assert np.abs(after - before).max() <= 8, "the emptied field does not show its value again"

    b = body(st, "b")
    app.click(*map(int, b["screen"]))
    st = app.wait(lambda s: s["selection"] == [b["id"]] and "inspector:density" in s["ui_rects"], 10, "b selected")
    st = app.settle()
    density = st["ui_rects"]["inspector:density"]
    before = crop(app.screenshot("density_before"), density)
    st = enter(app, density, clear=True)
    st = app.settle()
    assert body(st, "b")["density"] == pytest.approx(1.0) and not st["dirty"]
    after = crop(app.screenshot("emptied_density"), density)
    assert np.abs(after - before).max() <= 8, "the emptied density does not show its value again"

    # the angle is shown rounded (100 rad as "-30.42" deg): Enter alone must not set the rounding
    angle = body(st, "b")["angle"]
    st = enter(app, st["ui_rects"]["inspector:angle"])
    st = app.settle()
    assert body(st, "b")["angle"] == angle and not st["dirty"], (body(st, "b")["angle"], angle)

    # a real change is an edit, and the only one: one undo makes the scene clean again
    x0, y0, x1, y1 = rate
    app.click(int(x0 + 30), int((y0 + y1) / 2))
    app.settle()
    app.xdo("keydown", "ctrl")
    app.settle()
    app.key("a")
    app.settle()
    app.xdo("keyup", "ctrl")
    app.xdo("type", "--delay", "30", "120")
    app.key("Return")
    st = app.wait(lambda s: s["dt"] == pytest.approx(1 / 120), 10, "the step rate taken")
    assert st["dirty"]
    app.xdo("mousemove", 800, 300)             # the scene's: Ctrl+Z is its shortcut
    app.settle()
    app.key("ctrl+z")
    st = app.wait(lambda s: s["dt"] == dt, 10, "the step rate undone")
    assert not app.settle()["dirty"], "an Enter that changed nothing left an undo step behind"
