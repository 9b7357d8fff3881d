"""Switching solver mode while a scene runs (issue 5).

Modes share the body state and the contact arrays (including warm-start
impulses), so switching is choosing which kernel the next step calls.  A
pyramid run that cycles through every mode, one per second, must never go
non-finite nor make any box jump.
"""
import numpy as np
import pytest

import physics
from builders import finite, positions, pyramid_world


def pyramid(base, solver="soft_step"):
    return pyramid_world(base, solver)[0]


def centres(w):
    # the boxes' origins are their centres of mass
    return positions(w)


STACKING_MODES = ("soft_step", "sequential_impulse")


@pytest.mark.slow
def test_cycle_all_modes_every_second_during_pyramid():
    """Every mode in turn, one second each: never non-finite, and no switch kicks a box.

    The seed modes (impulse, penalty, hybrid) reproduce the report and cannot hold a
    210-box pyramid by themselves (it slumps within 2 s in each), so the jump measured
    here is the one a *switch* makes: how much a box's per-step displacement changes
    across the switch (0.1 m per step = a 6 m/s kick).  It is asserted for switches out of
    a stacking mode (the pyramid still intact); after a seed mode has let the pyramid
    slump, boxes are already falling and colliding fast (hybrid alone moves boxes
    0.45 m/step within 2 s), so those kicks are only printed, and must stay finite."""
    modes = physics.solvers_available()
    assert set(STACKING_MODES) <= set(modes)
    w = pyramid(20)
    before = centres(w)
    w.step()
    prev = centres(w)
    seconds = max(10, 2 * len(modes))
    last = None
    intact = True  # until a seed mode has run, the pyramid stands and every kick is the switch's
    for sec in range(seconds):
        last = w.solver if sec else None
        w.solver = modes[sec % len(modes)]
        for k in range(60):
            w.step()
            x = centres(w)
            assert finite(w), f"non-finite state in mode {w.solver}"
            if k == 0:
                kick = float(np.max(np.hypot(*((x - prev) - (prev - before)).T)))
                print(f"switch to {w.solver} at t={w.time:.2f}: kick {kick:.3f} m/step")
                if last in STACKING_MODES and intact:
                    assert kick < 0.1, f"switching {last} -> {w.solver} at t={w.time:.2f} kicked a box by {kick:.3f} m/step"
            before, prev = prev, x
        intact = intact and w.solver in STACKING_MODES


def test_cycle_stacking_modes_every_second_keeps_pyramid():
    """soft_step <-> sequential_impulse every second for 10 s: no box moves 0.1 m in a step,
    and the pyramid stands (top box within 0.1 m)."""
    w = pyramid(20)
    top = w.bodies[-1]
    p0 = np.array(top.position)
    prev = centres(w)
    for sec in range(10):
        w.solver = STACKING_MODES[sec % 2]
        for _ in range(60):
            w.step()
            x = centres(w)
            assert np.all(np.isfinite(x)), f"non-finite state in mode {w.solver}"
            jump = float(np.max(np.hypot(*(x - prev).T)))
            assert jump < 0.1, f"a box jumped {jump:.3f} m in one step in mode {w.solver} at t={w.time:.2f}"
            prev = x
    assert np.hypot(*(np.array(top.position) - p0)) < 0.1


def test_switch_keeps_warm_start_and_settings():
    w = pyramid(4, "soft_step")
    w.settings["substeps"] = 6
    for _ in range(30):
        w.step()
    # the accumulated normal impulses (what warm starting carries across a switch) are not public
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
