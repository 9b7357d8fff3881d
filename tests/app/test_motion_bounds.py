"""A body's motion fields have sane bounds too, refused beside the field in the user's terms: 1e300
typed into the velocity (a float field: it arrives as inf, said "too large to hold", not "got
inf") or the angular velocity (accepted before, then the next step failed: "started from a
non-finite energy ... during the 'begin' stage", the world reverted and paused).  The scene
then plays on without a fault."""
from __future__ import annotations

import pytest

from test_number_typing import refused_beside
from test_text_fields import fields_scene, select_body, type_into
from test_tools import body

pytestmark = [pytest.mark.app, pytest.mark.slow]


def test_velocity_and_spin_refused_in_the_users_terms(launch, tmp_path):
    app = launch(fields_scene(tmp_path / "fields.json"), "--paused")
    st = app.wait_ready(10)
    st = select_body(app, st, field="inspector:velocity")
    st = app.settle()
    type_into(app, st["ui_rects"]["inspector:velocity"], "1e300")
    st = app.wait(lambda s: s["edit_error"].startswith("velocity:"), 10, "the velocity refusal")
    assert st["edit_error"] == ("velocity: each component must be between -10000 and 10000 m/s "
                                "(got a number too large to hold, 0)"), st["edit_error"]
    refused_beside(app, app.settle(), "inspector:velocity", "velocity_refused")

    st = app.settle()
    type_into(app, st["ui_rects"]["inspector:angular_velocity"], "1e300")
    st = app.wait(lambda s: s["edit_error"].startswith("angular velocity:"), 10, "the spin refusal")
    assert st["edit_error"] == "angular velocity: must be between -10000 and 10000 rad/s (got 1e+300)"
    refused_beside(app, app.settle(), "inspector:angular_velocity", "spin_refused")
    assert not st["dirty"]

    # a sane value is taken, and the scene plays on from it
    st = app.settle()
    type_into(app, st["ui_rects"]["inspector:angular_velocity"], "20")
    st = app.wait(lambda s: body(s, "b")["angular_velocity"] == pytest.approx(20.0), 10, "the spin taken")
    assert st["dirty"] and st["edit_error"] == ""
    app.xdo("mousemove", 800, 300)
    app.settle()
    app.key("space")
    st = app.wait(lambda s: s["steps"] > 30, 30, "the scene to play")
    assert st["fault"] is None and st["n_bodies"] == 2, st["fault"]
