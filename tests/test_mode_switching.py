"""Switching solver mode while a scene runs (issue 5).

Modes share the body state and the contact arrays (including warm-start
impulses), so switching is choosing which kernel the next step calls.  A
pyramid run that cycles through every mode, one per second, must never go
non-finite nor make any box jump.
"""
import numpy as np
import pytest

import physics


def pyramid(base, solver="soft_step"):
    w = physics.World(gravity=(0.0, -10.0), dt=1 / 60, solver=solver, sleeping=False)
    w.add_body(physics.Polygon.box(2 * base + 20, 1), kind="static", position=(0, -0.5), friction=0.6)
    for i in range(base):
        for j in range(base - i):
            w.add_body(physics.Polygon.box(1, 1), position=(j - (base - i - 1) / 2.0, 0.5 + i), friction=0.6)
    return w


def centres(w):
    return w._bodies.view.x[: w._bodies.n].copy()


@pytest.mark.slow
def test_cycle_modes_every_second_during_pyramid():
    modes = physics.solvers_available()
    assert {"soft_step", "sequential_impulse"} <= set(modes)
    w = pyramid(20)
    prev = centres(w)
    worst = 0.0
    seconds = max(10, 2 * len(modes))
    for sec in range(seconds):
        w.solver = modes[sec % len(modes)]
        for _ in range(60):
            w.step()
            x = centres(w)
            assert np.all(np.isfinite(x)), f"non-finite state in mode {w.solver}"
            jump = float(np.max(np.hypot(*(x - prev).T)))
            worst = max(worst, jump)
            assert jump < 0.1, f"a box jumped {jump:.3f} m in one step in mode {w.solver} at t={w.time:.2f}"
            prev = x
    v = w._bodies.view.v[: w._bodies.n]
    assert np.all(np.isfinite(v))


def test_switch_keeps_warm_start_and_settings():
    w = pyramid(4, "soft_step")
    w.settings["substeps"] = 6
    for _ in range(30):
        w.step()
    jn = w._contacts.cur.jn[: w._contacts.n].copy()
    assert jn.sum() > 0
    w.solver = "sequential_impulse"
    w.settings["velocity_iterations"] = 12
    w.step()
    assert w.settings_for("soft_step")["substeps"] == 6
    w.solver = "soft_step"
    assert w.settings["substeps"] == 6
    w.solver = "sequential_impulse"
    assert w.settings["velocity_iterations"] == 12


@pytest.mark.parametrize("a,b", [("soft_step", "sequential_impulse"), ("sequential_impulse", "soft_step")])
def test_switch_back_and_forth_each_step_is_calm(a, b):
    w = pyramid(6, a)
    for _ in range(60):
        w.step()
    prev = centres(w)
    for k in range(240):
        w.solver = a if k % 2 else b
        w.step()
        x = centres(w)
        assert np.max(np.hypot(*(x - prev).T)) < 0.02
        prev = x
