"""A solver mode picked before its kernels are loaded (``app.mode_switch``), without a window: the
running mode goes on, the new one is asked for first, and the switch is one undoable edit once it
is ready; picking the running mode or a ready one cancels it; a reset keeps it, another scene
drops it; the first launch (nothing ready) switches at once.  The warmup is a stand-in that says
which modes are loaded (tests/app/test_mode_switch_pending.py runs the real one in a window)."""
from __future__ import annotations

import physics

from app.editor import Editor
from app.mode_switch import PendingSwitch
from app.notices import Notices


class FakeWarmup:
    """Which modes can step; records what is asked for."""

    def __init__(self, ready=("soft_step",)):
        self.ready = set(ready)
        self.asked: list[tuple] = []

    def can_step(self, solver, integrator, broadphase=None):
        return solver in self.ready

    def narrow_ready(self, unit):
        return True

    def joints_ready(self, solver, integrator):
        return solver in self.ready

    def prioritize(self, solver, integrator, broadphase=None, first=False):
        self.asked.append((solver, first))

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


def world():
    w = physics.World(gravity=(0, -10))
    w.solver = "soft_step"
    w.add_body(physics.Polygon.box(1, 1), position=(0, 1))
    return w


def setup(ready=("soft_step",)):
    ed = Editor(world(), None, Notices(), camera=None)
    warm = FakeWarmup(ready)
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
