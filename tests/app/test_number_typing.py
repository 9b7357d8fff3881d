"""Letters typed into a number field are refused in words beside the field, not dropped without a
word: "abc" in the step rate, "fast" in the time scale slider (Ctrl+click types into a slider),
and "abc" in a body's density in the inspector."""
from __future__ import annotations

import pytest

from sandbox_pixels import red_text_pixels
from test_compare import centre
from test_text_fields import fields_scene, select_body, type_into
from test_tools import body

pytestmark = pytest.mark.app


def refused_beside(app, st, field, name):
    """The refusal bubble is at the height of ``field`` and drawn (red text)."""
    x0, y0, x1, y1 = map(int, st["ui_rects"]["refusal"])
    fy0, fy1 = st["ui_rects"][field][1], st["ui_rects"][field][3]
    assert y0 <= fy1 and y1 >= fy0, "the refusal is not beside the field"
    assert 0 <= y0 and y1 <= 800, "the refusal runs off the window"
    assert x0 >= st["ui_rects"][field][0], "the refusal is not beside the field"
    assert red_text_pixels(app.screenshot(name), x0, y0, x1, y1) > 20, "the refusal is not shown"


def test_letters_in_number_fields_are_refused_beside_the_field(launch, tmp_path):
    app = launch(fields_scene(tmp_path / "fields.json"), "--paused")
    st = app.wait_ready(10)
    dt = st["dt"]
    type_into(app, st["ui_rects"]["sim:step_rate"], "abc")
    st = app.wait(lambda s: '"abc"' in s["edit_error"] and "refusal" in s["ui_rects"], 10, "the step rate refusal")
    assert st["edit_error"].startswith('step rate: "abc" is not a number'), st["edit_error"]
    # Enter took nothing (what was left in the field is the old value) and the refusal stays
    st = app.settle()
    assert st["dt"] == dt and not st["dirty"] and '"abc"' in st["edit_error"], (st["dirty"], st["edit_error"])
    refused_beside(app, st, "sim:step_rate", "step_rate_abc")
    # a number taken afterwards ends the refusal
    type_into(app, st["ui_rects"]["sim:step_rate"], "120")
    st = app.wait(lambda s: s["dt"] == pytest.approx(1 / 120), 10, "the step rate taken")
    assert st["edit_error"] == ""
    # a slider typed into (Ctrl+click) says it too
    app.xdo("keydown", "ctrl")
    app.click(*map(int, centre(st["ui_rects"]["sim:time_scale"])))
    app.xdo("keyup", "ctrl")
    app.settle()
    app.xdo("type", "--delay", "30", "fast")
    app.key("Return")
    st = app.wait(lambda s: s["edit_error"].startswith('time scale: "fast"'), 10, "the time scale refusal")
    assert app.settle()["time_scale"] == pytest.approx(1.0)
    # the inspector's fields say it too, with their own name
    st = select_body(app, st)
    st = app.settle()
    type_into(app, st["ui_rects"]["inspector:density"], "abc")
    st = app.wait(lambda s: s["edit_error"].startswith('density: "abc"'), 10, "the density refusal")
    assert '"abc" is not a number' in st["edit_error"], st["edit_error"]
    assert body(st, "b")["density"] == pytest.approx(1.0)
    refused_beside(app, app.settle(), "inspector:density", "density_abc")
