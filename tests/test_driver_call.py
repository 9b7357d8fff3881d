"""How Python reaches the step driver: the compiled overload called directly (physics/_jit.py:
``direct``), and the one number that says a table's arrays were replaced (store/table.py:
``GENERATION``), which the driver's pack is keyed on instead of every table's identity."""
import numpy as np
import pytest

import physics
from physics._jit import direct, kernel
from physics.step.soft_driver import soft_world_step
from physics.store.table import GENERATION


@kernel(entry=True)
def _axpy(a, x, y):
    for i in range(x.shape[0]):
        y[i] += a * x[i]
    return y.shape[0]


def test_direct_is_the_compiled_overload_and_computes_the_same():
    x, y1, y2 = np.arange(4.0), np.ones(4), np.ones(4)
    f = direct(_axpy, 2.0, x, y1)
    assert f is not _axpy, "direct gave back the dispatcher: no compiled entry was found"
    assert f(2.0, x, y1) == _axpy(2.0, x, y2) == 4
    np.testing.assert_array_equal(y1, y2)


def _world(n):
    w = physics.World(gravity=(0, -10))
    w.add_body(physics.Polygon.box(10, 0.5), position=(0, -0.25), kind="static")
    for i in range(n):
        w.add_body(physics.Polygon.box(0.5, 0.5), position=(1.1 * (i % 8) - 4, 0.3 + 1.1 * (i // 8)))
    return w


def test_the_step_calls_the_driver_compiled_for_its_pack():
    w = _world(3)
    w.step()
    oc = w._pipeline.one_call
    assert oc.P is not None, "the small box world should step through the driver"
    assert oc._call is not soft_world_step and callable(oc._call)


def _grown(w):
    """Step once, then add as many boxes as the body table holds (it must grow), and step on."""
    w.step()
    cap = w._store.bodies.capacity
    for i in range(cap):
        w.add_body(physics.Polygon.box(0.5, 0.5), position=(1.1 * (i % 8) - 4, 5.0 + 1.1 * (i // 8)))
    return cap


def test_replacing_a_tables_arrays_counts_and_the_driver_follows():
    """Growth (more bodies than the first capacity) replaces the arrays: GENERATION moves, the
    pack is rebuilt over the new arrays, and the world ends bit for bit where the same world
    stepped through the pipeline's stages ends (a stale pack would step the old arrays)."""
    w, ref = _world(3), _world(3)
    ref._pipeline.one_call.enabled = False
    w.step()
    ref.step()
    p0 = w._pipeline.one_call.P
    assert p0 is not None
    g0 = GENERATION[0]
    _grown(ref)
    cap = _grown(w)
    assert GENERATION[0] > g0 and w._store.bodies.capacity > cap
    for _ in range(30):
        w.step()
        ref.step()
    assert w._pipeline.one_call.P is not p0
    np.testing.assert_array_equal(w.state()["position"], ref.state()["position"])
    np.testing.assert_array_equal(w.state()["velocity"], ref.state()["velocity"])
