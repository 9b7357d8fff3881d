"""What one step may allocate is bounded by world.max_pairs (issue 20, item 4).

6,000 coincident circles (a 270 kB scene file) are 18 million candidate pairs and needed more
than 6 GB at the first step.  The broad phase counts pairs before it allocates for them; past
``max_pairs`` the step is refused.
"""
import resource

import pytest

import physics
from physics.collision.broadphase.limit import MAX_PAIRS
from physics.errors import SimulationError


def coincident(n, solver="soft_step"):
    w = physics.World(solver=solver)
    for _ in range(n):
        w.add_body(physics.Circle(0.5), position=(0.0, 0.0))
    return w


def peak_rss_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # Linux: kB


@pytest.mark.parametrize("method", ["sweep", "quadtree", "brute"])
def test_six_thousand_coincident_circles_are_refused_without_exhausting_memory(method):
    """18 M pairs > MAX_PAIRS = 1e6: SimulationError at 'broadphase' naming max_pairs, world.fault
    set, nothing moved, and the process's peak memory grows by less than 300 MB (it was > 6 GB;
    the bodies and the broad phase's per-body scratch need a few MB)."""
    w = coincident(6000)
    w.broadphase = method
    before = peak_rss_mb()
    with pytest.raises(SimulationError, match="max_pairs") as info:
        w.step()
    assert peak_rss_mb() - before < 300
    assert info.value.stage == "broadphase"
    assert w.fault is info.value
    assert w.steps == 0 and all(b.position == (0.0, 0.0) for b in w.bodies[:10])


def test_the_bound_is_the_worlds_and_exact():
    """20 coincident circles are 190 pairs: refused at max_pairs = 189, run at 190."""
    w = coincident(20)
    assert w.max_pairs == MAX_PAIRS
    w.max_pairs = 189
    with pytest.raises(SimulationError, match="190"):
        w.step()
    w.max_pairs = 190
    w.step()
    assert w.fault is None and w.steps == 1


@pytest.mark.parametrize("value", [0, -5, 1.5, "10", float("inf"), 10 ** 400, None, True])
def test_max_pairs_is_validated(value):
    w = coincident(2)
    with pytest.raises(ValueError, match="max_pairs"):
        w.max_pairs = value
    assert w.max_pairs == MAX_PAIRS


def test_the_narrow_phase_refuses_more_contact_rows_than_its_bound():
    """Handed more pairs than its bound, the narrow phase raises SimulationError at 'collide'
    naming the contact rows, before its tables change (collision/narrowphase/limit.py)."""
    import numpy as np

    from physics.collision import narrowphase
    w = coincident(20)
    w.step()
    s = w._store
    rows = s.contacts.n
    pairs = np.zeros((200, 2), dtype=np.int32)
    with pytest.raises(SimulationError, match="contact rows") as info:
        narrowphase.collide(w._pipeline.ctx, s.bodies.arrays, s.fixtures.arrays, s.verts.arrays, pairs, 200, s.contacts,
                            150)
    assert info.value.stage == "collide"
    assert s.contacts.n == rows


def test_contact_tables_grow_to_twice_the_need_but_never_past_the_bound():
    from physics.store.contacts import ContactBuffer
    c = ContactBuffer(256)
    c.ensure(300, 400)
    assert c.capacity == 400  # twice the need would have made 600
    c.ensure(300)
    assert c.capacity == 400
    c.ensure(500)
    assert c.capacity == 1000  # without a bound: twice the need (a waking pile asks for more each step)
    c.ensure(1100)
    assert c.capacity == 2200
