"""app.find_settings without a window: the scene the Find settings button sends to the tuner, and
Apply as one undoable edit (the real-window test is tests/app/test_find_settings.py)."""
from __future__ import annotations

from types import SimpleNamespace

import physics
from app.commands import History
from app.document import Document
from app.find_settings import apply_command, scene_copy


def world():
    w = physics.World(solver="soft_step")
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5), name="ground")
    w.add_body(physics.Circle(0.5), position=(0, 3), name="ball")
    return w


def state(w) -> dict:
    return {"solver": w.solver, "dt": w.dt, "integrator": w.integrator,
            "settings": {m: w.settings_for(m).to_dict() for m in w.solvers}}


def test_scene_copy_is_the_loaded_bodies_with_the_live_settings():
    w = world()
    editor = SimpleNamespace(world=w, doc=Document(w, None))
    w.bodies[1].position = (4.0, 7.0)         # the live world has moved on since it was loaded
    w.gravity = (0.0, -3.0)
    w.settings["substeps"] = 9
    w.dt = 1 / 120
    data = scene_copy(editor)
    ball = next(b for b in data["bodies"] if b["name"] == "ball")
    assert list(ball["position"]) == [0.0, 3.0]
    assert data["world"]["gravity"] == [0.0, -3.0] and data["world"]["dt"] == 1 / 120
    assert data["world"]["solver"] == "soft_step" and data["world"]["settings"]["substeps"] == 9


def test_apply_sets_mode_settings_dt_and_integrator_and_one_undo_restores_them():
    w = world()
    w.settings_for("sequential_impulse")["velocity_iterations"] = 20   # the user's own, to come back
    before = state(w)
    target = physics.World(solver="sequential_impulse").settings.to_dict()
    target.update(velocity_iterations=4, position_iterations=0)
    choice = {"solver": "sequential_impulse", "settings": target, "dt": w.dt * 0.5, "integrator": "rk4"}
    h = History()
    h.execute(None, apply_command(w, choice))
    assert w.solver == "sequential_impulse" and w.settings.to_dict() == target
    assert w.dt == before["dt"] * 0.5 and w.integrator == "rk4"
    assert h.undo(None) == "apply found settings"
    assert state(w) == before and not h.done
    h.redo(None)
    assert w.settings.to_dict() == target and w.integrator == "rk4"


def test_apply_of_what_is_already_set_changes_nothing():
    w = world()
    choice = {"solver": w.solver, "settings": w.settings.to_dict(), "dt": w.dt, "integrator": w.integrator}
    cmd = apply_command(w, choice)
    assert cmd.commands == []
