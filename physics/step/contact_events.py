"""Which fixture pairs touch, step to step: the arrays behind ``world.contact_events()``.

A contact row touches when one of its points is within ``linear_slop`` of touching
(depth > -slop, what ``world.contacts()`` shows) or took a normal impulse in the solve (a
speculative point that stopped an approach).  After each step one compiled pass
(:func:`touch_update`) merges the rows (sorted by key) with the last step's touching keys:
new keys are begins (their row numbers kept), keys gone are ends, unless the pair only went
to sleep (resting.py).  That is all a step pays; the Python events (physics/events.py) are
made from these arrays, the contact rows and the checkpoint's start-of-step velocities only
when ``world.contact_events()`` asks.  The merge runs inside the step's closing kernel
(frame.end_step): a kernel call of its own cost rain1000 ~17 us a step in dispatch and in
reading again rows the solve had left; an accepted step then only swaps the buffers (take).
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from .resting import kept

_NO_ENDS = np.zeros(0, np.int64)  # a step where nothing stopped touching (shared, never written)


@kernel
def touch_update(key, count, depth, jn, n, slop, prev, nprev, out, begin, absent):
    """Merge rows ``[:n]`` with the sorted touching keys ``prev[:nprev]``: the touching keys into
    ``out``, the rows that begin into ``begin``, the keys that stopped into ``absent``; returns
    the three counts."""
    nt = 0
    nb = 0
    na = 0
    ptr = 0
    for r in range(n):
        touching = False
        for p in range(count[r]):
            if depth[r, p] > -slop or jn[r, p] > 0.0:
                touching = True
        if not touching:
            continue
        k = key[r]
        while ptr < nprev and prev[ptr] < k:
            absent[na] = prev[ptr]
            na += 1
            ptr += 1
        if ptr < nprev and prev[ptr] == k:
            ptr += 1
        else:
            begin[nb] = r
            nb += 1
        out[nt] = k
        nt += 1
    while ptr < nprev:
        absent[na] = prev[ptr]
        na += 1
        ptr += 1
    return nt, nb, na


def _grown(a: np.ndarray, keep: int, cap: int) -> np.ndarray:
    """A zeroed array of ``cap`` entries holding ``a[:keep]``."""
    out = np.zeros(cap, a.dtype)
    out[:keep] = a[:keep]
    return out


class ContactTracker:
    """The touching keys (sorted) and the last step's begins (row numbers) and ends (keys)."""

    def __init__(self):
        self.keys = np.zeros(64, np.int64)
        self.n = 0
        self.begin = np.zeros(64, np.int64)
        self.nb = 0
        self._absent = np.zeros(64, np.int64)
        self.ends = self._absent[:0]
        # end_step's merge writes into these spares and an accepted step swaps them in (take):
        # a refused step leaves the last step's keys, begins and ends untouched
        self._keys2 = np.zeros(64, np.int64)
        self._begin2 = np.zeros(64, np.int64)
        self._absent2 = np.zeros(64, np.int64)

    def scratch(self, nc: int):
        """The merge's arguments for the ``nc`` rows (frame.end_step runs it, while the step's
        last kernel has the rows at hand): last step's keys, their count, and the spare outputs."""
        # the arrays and their spares grow together: they swap roles at every accepted step, so a
        # spare left short would be short again one step later (and the one-call step would stop
        # to grow it)
        if nc > min(len(self._keys2), len(self.keys)):
            self.keys, self._keys2 = _grown(self.keys, self.n, 2 * nc), np.zeros(2 * nc, np.int64)
        if nc > min(len(self._begin2), len(self.begin)):
            self.begin, self._begin2 = _grown(self.begin, self.nb, 2 * nc), np.zeros(2 * nc, np.int64)
        if self.n > min(len(self._absent2), len(self._absent)):
            # (``ends`` may be a view of the old array, which it keeps alive: nothing to copy)
            self._absent, self._absent2 = np.zeros(2 * self.n, np.int64), np.zeros(2 * self.n, np.int64)
        return self.keys, self.n, self._keys2, self._begin2, self._absent2

    def take(self, world, nt: int, nb: int, na: int) -> None:
        """The accepted step's merge (its three counts) becomes this step's keys, begins, ends."""
        self.keys, self._keys2 = self._keys2, self.keys
        self.begin, self._begin2 = self._begin2, self.begin
        self._absent, self._absent2 = self._absent2, self._absent
        self.n, self.nb = nt, nb
        if na:
            self.ends = self._absent[:na]
            self._keep_sleeping(world)
        else:  # the usual step: nothing ended (no view of the spare array made)
            self.ends = _NO_ENDS

    def _keep_sleeping(self, world) -> None:
        keep = kept(world, self.ends)
        if not keep.any():  # nothing sleeps (rain, a falling pile): every end stands
            return
        self.keys = np.union1d(self.keys[:self.n], self.ends[keep])
        self.n = len(self.keys)
        self.ends = self.ends[~keep].copy()

    def idle(self) -> None:
        """A step with no bodies at all: every touching pair ends."""
        self.ends = self.keys[:self.n].copy()
        self.n = 0
        self.nb = 0

    def state(self):
        """What a snapshot keeps: the touching keys."""
        return self.keys[:self.n].copy()

    def put(self, keys) -> None:
        """Restore the touching keys (the events of the last step are gone)."""
        self.keys = np.array(keys, np.int64)
        self.n = len(self.keys)
        self.nb = 0
        self.ends = self.keys[:0]
