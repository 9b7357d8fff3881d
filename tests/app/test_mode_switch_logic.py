"""A solver mode picked before its kernels are loaded (``app.mode_switch``), without a window: the
running mode goes on, the new one is asked for first, and the switch is one undoable edit once it
is ready; picking the running mode or a ready one cancels it; a reset keeps it, another scene
drops it; the first launch (nothing ready) switches at once.  The warmup is a stand-in that says
which modes are loaded (tests/app/test_mode_switch_pending.py runs the real one in a window).
An integrator or a broad phase picked before its kernels are loaded waits the same way, alone or
with a pending mode."""
from __future__ import annotations

import pytest

import physics

from app.editor import Editor
from app.mode_switch import PendingSwitch
from app.notices import Notices


class FakeWarmup:
    """Which modes can step (with any integrator or broad phase but those in ``cold``); records
    what is asked for."""

    def __init__(self, ready=("soft_step",), cold=()):
        self.ready = set(ready)
        self.cold = set(cold)
        self.asked: list[tuple] = []
        self.first: list[tuple] = []

    def can_step(self, solver, integrator, broadphase=None):
        return solver in self.ready and integrator not in self.cold and broadphase not in self.cold

    def narrow_ready(self, unit):
        return True

    def joints_ready(self, solver, integrator):
        return solver in self.ready

    def prioritize(self, solver, integrator, broadphase=None, first=False):
        self.asked.append((solver, first))
        if first:
            self.first.append((solver, integrator, broadphase))

    def want_unit(self, unit):
        self.asked.append((unit, False))

    want_apart = want_unit

    @staticmethod
    def cached(unit):
        return False

    def mode_units(self, solver, integrator, broadphase=None, joints=False):
        return [f"solve:{solver}:{integrator}"]

    def mode_progress(self, units):
        return 0.4, "~70 kernels left"


def world(solver="soft_step"):
    w = physics.World(gravity=(0, -10))
    w.solver = solver
    w.add_body(physics.Polygon.box(1, 1), position=(0, 1))
    return w


def setup(ready=("soft_step",), cold=(), solver="soft_step"):
    ed = Editor(world(solver), None, Notices(), camera=None)
    warm = FakeWarmup(ready, cold)
    return ed, warm, PendingSwitch(ed, warm)


def test_a_mode_not_compiled_waits_and_switches_once_ready():
    ed, warm, ms = setup()
    ed.switch_solver("penalty")
    assert ed.world.solver == "soft_step" and ms.mode == "penalty"
    assert ("penalty", True) in warm.asked, "the picked mode is asked for first"
    assert not ed.doc.history.done, "nothing is an edit until the switch happens"
    ms.update()
    assert ed.world.solver == "soft_step", "not ready yet: the running mode goes on"
    assert ms.describe()["from"] == "soft_step" and ms.describe()["progress"] == 0.4
    warm.ready.add("penalty")
    ms.update()
    assert ed.world.solver == "penalty" and ms.mode is None
    ed.undo()                                   # the switch is one undoable edit, as a click was
    assert ed.world.solver == "soft_step" and ms.mode is None


def test_the_running_mode_or_a_ready_one_cancels_it():
    ed, warm, ms = setup(ready=("soft_step", "impulse"))
    ed.switch_solver("penalty")
    ed.switch_solver("soft_step")
    assert ms.mode is None and ed.world.solver == "soft_step"
    warm.ready.add("penalty")
    ms.update()
    assert ed.world.solver == "soft_step", "a cancelled switch must not happen later"
    warm.ready.discard("penalty")
    ed.switch_solver("penalty")
    ed.switch_solver("hybrid")                   # another mode not ready: it replaces the first
    assert ms.mode == "hybrid"
    ed.switch_solver("impulse")                  # a ready one: at once, and nothing pending
    assert ed.world.solver == "impulse" and ms.mode is None


def test_first_launch_switches_at_once():
    ed, _, ms = setup(ready=())
    ed.switch_solver("penalty")
    assert ed.world.solver == "penalty" and ms.mode is None


def test_a_reset_keeps_it_and_another_scene_drops_it():
    ed, warm, ms = setup()
    ed.switch_solver("penalty")
    ed.set_document(world(), None, keep_camera=True)        # what a reset does
    assert ms.mode == "penalty"
    warm.ready.add("penalty")
    ms.update()
    assert ed.world.solver == "penalty", "the reset scene switches once ready"
    warm.ready.discard("penalty")
    ed.switch_solver("soft_step")
    ed.switch_solver("hybrid")
    ed.set_document(world(), None)                          # another scene opened
    assert ms.mode is None and any("cancelled" in m[0] for m in ed.notices.items)
    warm.ready.add("hybrid")
    ms.update()
    assert ed.world.solver == "soft_step", "a switch asked for in one scene must not reach another"


def test_it_waits_for_the_release_of_a_mouse_drag():
    ed, warm, ms = setup()
    ed.switch_solver("penalty")
    warm.ready.add("penalty")
    ed.tool_joints.add(99)                       # the select tool holds a body
    ms.update()
    assert ed.world.solver == "soft_step"
    ed.tool_joints.clear()
    ms.update()
    assert ed.world.solver == "penalty"


def test_a_mode_applied_another_way_cancels_it():
    ed, warm, ms = setup(ready=("soft_step", "impulse"))
    ed.switch_solver("penalty")
    ed.world.solver = "impulse"                  # what Find settings' apply does, then on_mode
    for cb in ed.on_mode:
        cb("impulse", ed.world.integrator)
    assert ms.mode is None
    warm.ready.add("penalty")
    ms.update()
    assert ed.world.solver == "impulse"


def test_an_integrator_not_compiled_waits_and_applies_once_ready():
    ed, warm, ms = setup(ready=("impulse",), cold=("rk4",), solver="impulse")  # a mode that uses it
    assert ed.world.integrator == "symplectic_euler"
    ed.set_integrator("rk4")
    assert ed.world.integrator == "symplectic_euler" and ms.integrator == "rk4" and ms.mode is None
    assert ("impulse", "rk4", "brute") in warm.first, "the picked combination is asked for first"
    assert not ed.doc.history.done, "nothing is an edit until it is applied"
    d = ms.describe()
    assert d["integrator"] == "rk4" and d["from_integrator"] == "symplectic_euler" and d["mode"] is None
    assert ms.label() == "integrator rk4" and ms.running_label() == "integrator symplectic_euler"
    ms.update()
    assert ed.world.integrator == "symplectic_euler", "not ready yet: the running integrator goes on"
    warm.cold.discard("rk4")
    ms.update()
    assert ed.world.integrator == "rk4" and not ms.active
    assert len(ed.doc.history.done) == 1
    ed.undo()                                   # one undoable edit, as a pick of a ready one was
    assert ed.world.integrator == "symplectic_euler" and not ms.active


def test_a_broadphase_not_compiled_waits_and_applies_once_ready():
    ed, warm, ms = setup(cold=("quadtree",))
    ed.set_broadphase("quadtree")
    assert ed.world.broadphase == "auto" and ms.broadphase == "quadtree"
    assert ("soft_step", "symplectic_euler", "quadtree") in warm.first
    ms.update()
    assert ed.world.broadphase == "auto"
    warm.cold.discard("quadtree")
    ms.update()
    assert ed.world.broadphase == "quadtree" and not ms.active
    ed.undo()
    assert ed.world.broadphase == "auto"


def test_a_ready_integrator_or_broadphase_is_set_at_once():
    ed, _, ms = setup(cold=("quadtree",))
    ed.set_integrator("euler")
    ed.set_broadphase("brute")          # what "auto" runs for one body: nothing to compile
    assert ed.world.integrator == "euler" and ed.world.broadphase == "brute" and not ms.active
    assert len(ed.doc.history.done) == 2


def test_an_integrator_the_mode_does_not_use_applies_at_once_and_says_so():
    ed, _, ms = setup(cold=("rk4",))          # soft_step integrates its own way: nothing to compile
    with pytest.warns(UserWarning, match="not used by solver 'soft_step'"):
        ed.set_integrator("rk4")
    assert ed.world.integrator == "rk4" and not ms.active
    assert any("soft_step does not use integrator rk4" in m[0] for m in ed.notices.items)


def test_the_running_integrator_or_broadphase_cancels_it():
    ed, warm, ms = setup(ready=("impulse",), cold=("rk4", "quadtree"), solver="impulse")
    ed.set_integrator("rk4")
    ed.set_broadphase("quadtree")
    assert ms.choice == {"integrator": "rk4", "broadphase": "quadtree"}
    assert ms.label() == "integrator rk4, broad phase quadtree"
    ed.set_integrator("symplectic_euler")        # the running one: that part is cancelled
    assert ms.choice == {"broadphase": "quadtree"}
    ed.set_broadphase("auto")
    assert not ms.active and any("cancelled" in m[0] for m in ed.notices.items)
    warm.cold.clear()
    ms.update()
    assert (ed.world.integrator, ed.world.broadphase) == ("symplectic_euler", "auto"), \
        "a cancelled pick must not be applied later"
    assert not ed.doc.history.done


def test_a_mode_and_an_integrator_wait_together():
    ed, warm, ms = setup(cold=("rk4",))
    ed.switch_solver("penalty")
    ed.set_integrator("rk4")
    assert ms.choice == {"solver": "penalty", "integrator": "rk4"}
    assert ("penalty", "rk4", "brute") in warm.first, "the combination picked is what compiles first"
    warm.ready.add("penalty")
    ms.update()
    assert ed.world.solver == "soft_step", "penalty is ready, but not with rk4"
    warm.cold.clear()
    ms.update()
    assert (ed.world.solver, ed.world.integrator) == ("penalty", "rk4") and not ms.active
    ed.undo()
    ed.undo()
    assert (ed.world.solver, ed.world.integrator) == ("soft_step", "symplectic_euler")


def test_an_integrator_ready_with_the_pending_mode_applies_both():
    ed, warm, ms = setup(ready=("soft_step",), cold=("rk4",))
    ed.switch_solver("penalty")
    warm.ready.add("penalty")
    warm.cold.clear()
    ed.set_integrator("euler")                   # (penalty, euler) is ready: both now
    assert (ed.world.solver, ed.world.integrator) == ("penalty", "euler") and not ms.active


def test_a_broadphase_pick_waits_for_the_release_of_a_mouse_drag():
    ed, warm, ms = setup(cold=("sweep",))
    ed.set_broadphase("sweep")
    warm.cold.clear()
    ed.tool_joints.add(99)
    ms.update()
    assert ed.world.broadphase == "auto"
    ed.tool_joints.clear()
    ms.update()
    assert ed.world.broadphase == "sweep"
