"""``World.threads``: a step split between threads gives the numbers one thread gives, bit for bit.

The split loops (physics/threads.py) run only past a size, so the scenes here are checked to be
past it: a test on a scene that never splits could not fail.
"""
import numpy as np
import pytest

import physics
from builders import pyramid_world, state_digest
from physics import threads
from physics._jit import kernel
from physics.collision.narrowphase.carry import move_row
from physics.constraints.colouring import LANES
from physics.store.contacts import CONTACT_FIELDS
from physics.store.table import allocate
from physics.store.table_type import make_table

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
    # and the narrow phase's pairs (at least one per row)
    assert n >= 2 * threads.MIN_BODIES and blocks >= 2 * threads.MIN_BLOCKS
    assert rows >= 2 * max(threads.MIN_SLOTS, threads.MIN_PAIRS)
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


@kernel(entry=True, cache=False)
def _move(CF, CI, Cpt, dst, src):
    move_row(make_table("contacts", (CF, CI, Cpt)), dst, src)


def test_a_moved_contact_row_keeps_every_field():
    """The split narrow phase closes the gaps between the threads' runs with move_row
    (collision/narrowphase/collide.py): a field it forgot would be lost on many threads only."""
    cols = allocate(CONTACT_FIELDS, 4)
    rng = np.random.default_rng(1)
    for name, a in cols.items():
        a[...] = rng.integers(1, 100, a.shape) if a.dtype.kind in "iu" else rng.random(a.shape)
    before = {k: np.array(v) for k, v in cols.items()}
    _move(*cols.flat, 1, 3)
    for name in CONTACT_FIELDS:
        assert np.array_equal(cols[name][1], before[name][3]), name
        assert np.array_equal(cols[name][[0, 2, 3]], before[name][[0, 2, 3]]), name


def _child_digest(q):
    w = _run(60, 10, threads.available())  # 1 in a forked child of a process that ran OpenMP
    q.put((threads.available(), state_digest(w)))


@TWO
def test_a_forked_child_steps_on_one_thread():
    """multiprocessing forks by default on Linux; GNU OpenMP stops a forked child that starts a
    parallel region, so after the parent ran two threads the child must step on one."""
    import multiprocessing as mp
    ref = state_digest(_run(60, 10, 2))  # the parent's pool has run
    ctx = mp.get_context("fork")
    q = ctx.Queue()
    p = ctx.Process(target=_child_digest, args=(q,))
    p.start()
    p.join(300)
    assert p.exitcode == 0
    assert q.get(timeout=5) == (1, ref)
