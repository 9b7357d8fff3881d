"""The integrator combo in a mode that integrates its own way: picking rk4 in soft_step (real
clicks in the solver panel) is taken and kept, and the window says that soft_step does not use
it, which the core's console warning alone would leave unseen; switching to impulse, a mode that
uses it, says nothing more about it.  (Before, the pick changed nothing in the scene and said
nothing.)"""
from __future__ import annotations

import pytest
from sandbox_pixels import ROOT
from test_mode_switch_pending import centre, visible

pytestmark = [pytest.mark.app]

NOTE = "soft_step does not use integrator rk4"


def pick(app, combo, item):
    st = visible(app, combo)
    app.click(*centre(st["ui_rects"][combo]))
    st = app.wait(lambda s: item in s["ui_rects"], 20, f"{combo}'s list")
    st = app.settle()
    app.click(*centre(st["ui_rects"][item]))


def test_an_integrator_soft_step_does_not_use_is_kept_and_the_window_says_so(launch):
    app = launch(ROOT / "scenes" / "default.json")
    app.wait_ready()
    pick(app, "integrator_combo", "integrator:rk4")
    st = app.wait(lambda s: s["ui_values"]["solver_settings"]["integrator"] == "rk4", 300, "rk4 taken")
    assert st["solver"] == "soft_step"
    st = app.wait(lambda s: any(NOTE in m for m in s["messages"]), 20, "the note in the window")
    note = next(m for m in st["messages"] if NOTE in m)
    assert "its own way (symplectic Euler in sub-steps)" in note, note
    app.screenshot("integrator_note")            # look at it: the notice names why
    assert not any("compiles first" in m for m in st["messages"]), "nothing to compile for it"
    n_notes = sum(NOTE in m for m in st["messages"])

    pick(app, "solver_combo", "solver:impulse")
    st = app.wait(lambda s: s["solver"] == "impulse", 600, "impulse")
    st = app.frames(4)
    assert st["ui_values"]["solver_settings"]["integrator"] == "rk4", "kept for the mode that uses it"
    assert sum(NOTE in m for m in st["messages"]) == n_notes, "impulse uses rk4: nothing more to say"
    assert not st["fault"] and not st["gl_errors"]
