"""How many threads a step may use (``World.threads``), and the threading layer under them.

The step splits its wide loops (the broad phase's sweep, the narrow phase's pairs, the
manifolds' preparation, a colour's contact blocks, the bodies' integration and geometry) into one
chunk per thread with numba's ``prange``; every chunk computes exactly what one thread would (a
colour's chunks share no moving body: Box2D v3's graph colouring), so the results are the same
bits for any thread count.

numba runs ``prange`` on a threading layer: OpenMP or TBB start a parallel region in about a
microsecond here; its fallback ("workqueue") takes ~100 us per region
(../shared/notes/solver-speed.md), more than the work it would split, so without OpenMP or TBB
the step stays on one thread.

Only the one-call step splits (step/soft_driver.py), and only when the world is large enough to
gain (``SPLIT_SIZE``): the split code is compiled into a second driver, so a small world does
not pay for compiling numba's parallel loops.  The kernels take the thread count ``nthr`` as
None (the serial build: numba prunes the split branches) or an int (``threads_of``).

GNU OpenMP cannot run in a child that ``fork()`` made of a process that used it (numba stops
the child: "fork() called from a process already using GNU OpenMP").  multiprocessing forks by
default on Linux, so in such a child every world steps on one thread (``usable``), whatever
``World.threads`` says; a spawned process starts its own pool.
"""
from __future__ import annotations

import importlib
import os

from numba import types
from numba.core import config
from numba.extending import overload

from ._jit import kernel

#: below this many bodies, manifold blocks (of colouring.LANES) or slots per thread, a loop
#: runs on one thread: starting a parallel region costs about a microsecond, a block's solve
#: about 0.1 us
MIN_BODIES = 512
MIN_BLOCKS = 24
MIN_SLOTS = 256
MIN_PAIRS = 256
#: bodies or fixtures from which the one-call step is built with its split loops (two threads'
#: worth of MIN_BODIES: below it no loop would split)
SPLIT_SIZE = 2 * MIN_BODIES

_LAYER: list = []
FORKED = [False]  # this process is a fork of one whose OpenMP pool ran (module doc)


def layer() -> str | None:
    """The threading layer numba can start ("tbb" or "omp", in numba's own order of
    preference), or None when only its slow fallback is there (or the user asked for it)."""
    if not _LAYER:
        want = str(config.THREADING_LAYER).lower()
        candidates = {"default": ("tbb", "omp"), "threadsafe": ("tbb", "omp"), "forksafe": ("tbb", "omp"),
                      "safe": ("tbb",), "tbb": ("tbb",), "omp": ("omp",)}.get(want, ())
        found = None
        for name in candidates:
            try:
                importlib.import_module(f"numba.np.ufunc.{name}pool")
            except ImportError:
                continue
            found = name
            break
        _LAYER.append(found)
    return _LAYER[0]


def start() -> None:
    """Start numba's thread pool now, before any kernel loads from the cache: a cached kernel
    that calls a parallel loop links against the pool's scheduler (``allocate_sched``), which
    numba registers only when it starts the pool, and it starts it when it compiles a parallel
    loop, not when it loads one."""
    if layer():
        from numba.np.ufunc.parallel import _launch_threads
        _launch_threads()
        if layer() == "omp":
            os.register_at_fork(after_in_child=_forked)


def _forked() -> None:
    FORKED[0] = True


def available() -> int:
    """The most threads a step can use here: numba's thread count (the machine's cores unless
    ``NUMBA_NUM_THREADS`` says otherwise) with OpenMP or TBB, else 1 (and 1 in a forked child
    of a process that started OpenMP: module doc)."""
    return int(config.NUMBA_NUM_THREADS) if layer() and not FORKED[0] else 1


def usable(n: int) -> int:
    """The threads a step asked to use ``n`` runs on in this process."""
    return 1 if FORKED[0] else n


@kernel(forceinline=True)
def share(n, t, nthr):
    """Thread ``t``'s run ``lo..hi-1`` of ``n`` items split between ``nthr`` threads: runs of
    floor(n / nthr) or one more, in order, which together cover 0..n-1 once."""
    return n * t // nthr, n * (t + 1) // nthr


def threads_of(split, c):
    """The thread count for the split loops: None when ``split`` is None (the serial build, in
    which numba prunes them), else the step context ``c``'s count.  Resolved from the argument's
    type while numba types the caller (store/optional.py says why a plain ``if`` would not do)."""
    return None if split is None else c.threads


@overload(threads_of, inline="always")
def _threads_of(split, c):
    if isinstance(split, types.NoneType):
        return lambda split, c: None
    return lambda split, c: c.threads


def check(value) -> int:
    """``value`` as a thread count, or ValueError naming ``threads``."""
    if isinstance(value, bool) or not isinstance(value, int) and not hasattr(value, "__index__"):
        raise ValueError(f"threads must be a whole number, got {value!r}")
    n = int(value)
    top = available()
    if not 1 <= n <= top:
        why = (" (a forked child of a process that ran OpenMP)" if FORKED[0] else
               "" if layer() else " (numba has no OpenMP or TBB threading layer here)")
        raise ValueError(f"threads must be between 1 and {top} on this machine{why}, got {n}")
    return n


start()
