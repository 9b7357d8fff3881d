"""The world's integrator setting in a mode that integrates its own way (soft_step,
sequential_impulse) has no effect: setting it warns, ``info()`` and ``python -m physics info`` say
why, and the setting is kept for a switch to a mode that uses it.  The claim "no effect" is
checked, not assumed: the same world stepped with rk4 set and with the default ends bit for bit
alike in those modes, and differently in the impulse mode, which uses it."""
from __future__ import annotations

import subprocess
import sys
import warnings

import numpy as np
import pytest

from physics import Circle, Polygon, World
from physics.scene import save_scene

OWN = ("soft_step", "sequential_impulse")


def scene(solver: str, integrator: str = "symplectic_euler") -> World:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        w = World(solver=solver, integrator=integrator)
    w.add_body(Polygon.box(10, 1), kind="static", position=(0, -0.5))
    w.add_body(Polygon.box(1, 1), position=(0, 1.0), angle=0.3)
    b = w.add_body(Circle(0.3), position=(1.5, 2.0), velocity=(-1.0, 0.0))
    w.add_spring(b, None, anchor_b=(1.5, 4.0), stiffness=40.0, damping=0.2)
    return w


def end_state(w: World, steps: int = 120) -> np.ndarray:
    for _ in range(steps):
        w.step()
    s = w.state()
    return np.concatenate([s["position"].ravel(), s["angle"], s["velocity"].ravel(), s["angular_velocity"]])


@pytest.mark.parametrize("solver", OWN)
def test_setting_an_integrator_the_mode_does_not_use_warns_and_says_why(solver):
    w = scene(solver)
    with pytest.warns(UserWarning, match=rf"integrator 'rk4' is not used by solver '{solver}'") as rec:
        w.integrator = "rk4"
    assert "impulse, penalty, hybrid" in str(rec[0].message)
    assert w.integrator == "rk4", "kept for a switch to a mode that uses it"
    assert "its own way" in w.info()["integrator_note"]
    with pytest.warns(UserWarning, match="not used"):
        World(solver=solver, integrator="euler")


def test_no_warning_where_the_integrator_applies_or_is_the_modes_own():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        w = World(solver="impulse", integrator="rk4")
        w.integrator = "euler"
        assert w.info()["integrator_note"] == ""
        World(solver="soft_step").integrator = "symplectic_euler"


@pytest.mark.parametrize("solver", OWN)
def test_the_integrator_indeed_changes_nothing_in_these_modes(solver):
    assert np.array_equal(end_state(scene(solver, "rk4")), end_state(scene(solver)))


def test_but_it_does_in_a_mode_that_uses_it():
    assert not np.array_equal(end_state(scene("impulse", "rk4")), end_state(scene("impulse")))


def test_cli_info_says_why(tmp_path):
    w = scene("soft_step", "rk4")
    path = tmp_path / "rk4.json"
    save_scene(w, path)
    out = subprocess.run([sys.executable, "-m", "physics", "info", str(path)], capture_output=True, text=True, check=True,
                         timeout=600).stdout
    assert "integrator: rk4" in out and "is not used by solver 'soft_step'" in out, out
