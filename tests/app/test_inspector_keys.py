"""The inspector under the pointer: a refusal does not move the fields (the next click lands where
the user aimed), keys typed after a refused value never reach the scene as shortcuts, and after
Enter takes a value the keyboard is the scene's again (Space pauses)."""
from __future__ import annotations

import pytest

from sandbox_pixels import red_text_pixels
from test_text_fields import fields_scene, select_body, type_into
from test_tools import body

pytestmark = pytest.mark.app

FIELDS = ("inspector:density", "inspector:angle")


def test_refusals_keep_the_fields_in_place_and_keys_out_of_the_scene(launch, tmp_path):
    app = launch(fields_scene(tmp_path / "fields.json"), "--paused")
    st = app.wait_ready(10)
    st = select_body(app, st)
    st = app.settle()
    before = {k: st["ui_rects"][k] for k in FIELDS}
    overlays = st["overlays"]
    # a refused density: the message is shown, no field moved
    type_into(app, st["ui_rects"]["inspector:density"], "0")
    st = app.wait(lambda s: "density" in s["edit_error"] and "refusal" in s["ui_rects"], 10, "the refusal")
    st = app.settle()
    assert {k: st["ui_rects"][k] for k in FIELDS} == before, "the refusal moved the fields"
    x0, y0, x1, y1 = map(int, st["ui_rects"]["refusal"])
    assert abs(y0 - before["inspector:density"][1]) < 10, "the refusal is not beside the field"
    assert red_text_pixels(app.screenshot("refused_density"), x0, y0, x1, y1) > 20, "the refusal is not shown"
    # typing on after the refusal (as if the field still had the keyboard) fires no shortcut
    app.xdo("type", "--delay", "40", "1e9abc")
    st = app.settle()
    assert st["tool"] == "select" and st["overlays"] == overlays and not st["scene_keys"], (st["tool"], st["overlays"])
    # a value taken with Enter gives the keyboard back: Space plays, and the refusal is gone
    type_into(app, st["ui_rects"]["inspector:density"], "2")
    st = app.wait(lambda s: body(s, "b")["density"] == pytest.approx(2.0), 10, "the density taken")
    st = app.settle()
    assert {k: st["ui_rects"][k] for k in FIELDS} == before, "the refusal's end moved the fields"
    app.key("space")
    st = app.wait(lambda s: s["running"], 10, "Space to play after Enter")
    assert st["edit_error"] == ""
