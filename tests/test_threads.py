"""``World.threads``: a step split between threads gives the numbers one thread gives, bit for bit.

The split loops (physics/threads.py) run only past a size, so the scenes here are checked to be
past it: a test on a scene that never splits could not fail.
"""
import numpy as np
import pytest

import physics
from builders import pyramid_world, state_digest
from physics import threads
from physics.constraints.colouring import LANES

TWO = pytest.mark.skipif(threads.available() < 2, reason="numba can run one thread here (one core, or no "
                                                         "OpenMP/TBB threading layer)")


def test_default_is_what_numba_can_run():
    assert physics.World().threads == threads.available()


@pytest.mark.parametrize("bad", [0, -1, 1.5, "2", True, threads.available() + 1])
def test_bad_counts_are_refused_naming_threads(bad):
    w = physics.World()
    with pytest.raises(ValueError, match="threads"):
        w.threads = bad
    assert w.threads == threads.available()  # unchanged


def _split_sizes(w):
    """(bodies, largest colour's full blocks, contact rows) of the world as it stands."""
    c = w._store.contacts
    colours = np.asarray(c.cur.colour[:c.n])
    per = np.bincount(colours[colours >= 0])
    return w._store.bodies.n, int(per.max()) // LANES, c.n


def _run(base, steps, n_threads):
    w, _ = pyramid_world(base)
    w.threads = n_threads
    for _ in range(steps):
        w.step()
    return w


@TWO
def test_two_threads_give_one_threads_bits():
    one = _run(60, 40, 1)
    two = _run(60, 40, 2)
    n, blocks, rows = _split_sizes(two)
    # every split loop ran on two threads: bodies, the largest colour's blocks, the prepared slots
    assert n >= 2 * threads.MIN_BODIES and blocks >= 2 * threads.MIN_BLOCKS and rows >= 2 * threads.MIN_SLOTS
    assert state_digest(two) == state_digest(one)


@TWO
def test_thread_count_changes_between_steps():
    """Switching the count while the scene runs changes nothing either."""
    w, _ = pyramid_world(60)
    ref, _ = pyramid_world(60)
    ref.threads = 1
    for k in range(30):
        w.threads = 1 + k % 2
        w.step()
        ref.step()
    assert state_digest(w) == state_digest(ref)
