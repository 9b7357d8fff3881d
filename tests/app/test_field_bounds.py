"""Fields refuse values out of their sane range with a message in the user's own terms, where the
user is looking: gravity 1e12 (it ejected every body), density 1e30 (said as typed, not as the
float32 the field made of it); the mass can be set (through the density), not only the density."""
from __future__ import annotations

import pytest

from sandbox_pixels import red_text_pixels
from test_text_fields import fields_scene, type_into
from test_tools import body

pytestmark = pytest.mark.app


@pytest.mark.slow
def test_gravity_and_density_refusals_in_the_users_terms(launch, tmp_path):
    app = launch(fields_scene(tmp_path / "fields.json"), "--paused")
    st = app.wait_ready(10)
    type_into(app, st["ui_rects"]["sim:gravity"], "1e12")
    st = app.wait(lambda s: s["edit_error"], 10, "the gravity refusal")
    assert "gravity" in st["edit_error"] and "between -1000 and 1000" in st["edit_error"], st["edit_error"]
    assert "got 1e+12" in st["edit_error"] and not st["dirty"], st["edit_error"]
    st = app.settle()
    st = app.wait(lambda s: "refusal" in s["ui_rects"], 10, "the refusal beside the field")
    x0, y0, x1, y1 = map(int, st["ui_rects"]["refusal"])
    assert abs(y0 - st["ui_rects"]["sim:gravity"][1]) < 10
    assert red_text_pixels(app.screenshot("gravity_refused"), x0, y0, x1, y1) > 20
    b = body(st, "b")
    app.click(*map(int, b["screen"]))
    st = app.wait(lambda s: s["selection"] == [b["id"]] and "inspector:density" in s["ui_rects"], 10, "b selected")
    st = app.settle()
    type_into(app, st["ui_rects"]["inspector:density"], "1e30")
    st = app.wait(lambda s: "density" in s["edit_error"], 10, "the density refusal")
    assert "1e+30" in st["edit_error"] and "1.00000001" not in st["edit_error"], st["edit_error"]
    assert body(st, "b")["density"] == pytest.approx(1.0)
    # the mass field sets the mass (the density follows); a mass of 0 is refused in kilograms
    st = app.settle()
    for _ in range(10):                  # scroll the panel to it
        if st["ui_rects"]["inspector:mass"][3] < 760:
            break
        app.xdo("mousemove", 150, 600, "click", "5", "click", "5")
        st = app.settle()
    type_into(app, st["ui_rects"]["inspector:mass"], "2.88")
    st = app.wait(lambda s: body(s, "b")["mass"] == pytest.approx(2.88), 10, "the mass set")
    assert body(st, "b")["density"] == pytest.approx(2.0)        # the box is 1.2 m x 1.2 m
    st = app.settle()
    type_into(app, st["ui_rects"]["inspector:mass"], "0")
    st = app.wait(lambda s: s["edit_error"].startswith("mass:"), 10, "the mass refusal")
    assert "got 0 kg" in st["edit_error"] and body(st, "b")["mass"] == pytest.approx(2.88)
