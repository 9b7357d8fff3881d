"""A pair_filter callback runs inside step(): the world refuses to be changed from it (a removed
body used to leave step() with a bare KeyError and world.fault None), and whatever the callback
raises refuses the step like any other: SimulationError, world.fault set, the world as before."""
import numpy as np
import pytest

import physics


def _scene():
    w = physics.World()
    ground = w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5), name="ground")
    ball = w.add_body(physics.Circle(0.3), position=(0, 0.31), name="ball")
    other = w.add_body(physics.Circle(0.3), position=(3, 2), name="other")
    return w, ground, ball, other


EDITS = {
    "remove a body": lambda w, o: w.remove(o),
    "add a body": lambda w, o: w.add_body(physics.Circle(1.0), position=(9, 9)),
    "add a spring": lambda w, o: w.add_spring(o, None, anchor_b=(3, 5)),
    "add a joint": lambda w, o: w.add_joint("revolute", o, None, anchor=(3, 2)),
    "add a fixture": lambda w, o: o.add_fixture(physics.Circle(0.1)),
    "reweigh a fixture": lambda w, o: setattr(o.fixtures[0], "density", 5.0),
    "step again": lambda w, o: w.step(),
    "switch the solver": lambda w, o: setattr(w, "solver", "sequential_impulse"),
}


@pytest.mark.parametrize("edit", list(EDITS))
def test_edits_from_inside_pair_filter_are_refused_and_the_step_is_reverted(edit):
    w, ground, ball, other = _scene()
    before = w.state()
    counts = (len(w.bodies), len(w.springs), len(w.joints), len(other.fixtures), w.solver)

    def fn(a, b):
        EDITS[edit](w, other)
        return True
    w.pair_filter = fn
    with pytest.raises(physics.SimulationError, match="cannot be changed from inside a callback") as info:
        w.step()
    assert w.fault is info.value and "pair_filter" in str(info.value)
    assert (len(w.bodies), len(w.springs), len(w.joints), len(other.fixtures), w.solver) == counts
    after = w.state()
    assert all(np.array_equal(before[k], after[k]) for k in before.dtype.names)
    assert w.steps == 0 and other.alive
    w.pair_filter = None  # the world is whole: it steps on, and can be edited again
    w.step()
    w.remove(other)
    assert w.fault is None and len(w.bodies) == 2


def test_any_exception_from_the_callback_refuses_the_step():
    w, *_ = _scene()

    def fn(a, b):
        raise KeyError("mine")
    w.pair_filter = fn
    with pytest.raises(physics.SimulationError, match="KeyError") as info:
        w.step()
    assert w.fault is info.value and isinstance(info.value.__cause__, KeyError)


def test_reading_the_world_from_the_callback_is_allowed():
    w, ground, ball, other = _scene()
    seen = []
    w.pair_filter = lambda a, b: (seen.append((a.body.name, b.body.name, len(w.bodies))), True)[1]
    w.step()
    assert ("ground", "ball", 3) in seen and w.fault is None
