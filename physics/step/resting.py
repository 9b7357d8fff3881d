"""Pairs that left the step's pairs only because they sleep: their touching or overlap goes on.

The broad phase skips a pair the solver could not move (collision/broadphase/filter.py
``can_pair``: both asleep, or asleep against static).  A contact or sensor overlap of such a
pair has not ended; the event trackers keep it (Box2D keeps a sleeping island's contacts too).
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from ..store import DYNAMIC, STATIC
from ..store.contacts import PAIR_LOW as LOW


@kernel(entry=True)
def any_asleep(awake, kind, nf):
    """Is one of the ``nf`` fixtures on a sleeping dynamic body?  Stops at the first."""
    for i in range(nf):
        if awake[i] == 0 and kind[i] == DYNAMIC:
            return True
    return False


def kept(world, keys: np.ndarray) -> np.ndarray:
    """For each fixture-pair key (id << 32 | id) that left this step's pairs: True when both
    fixtures live and the pair was skipped for sleeping (F.kind/F.awake as the step's broad
    phase saw them)."""
    F = world._store.fixtures.view
    nf = world._store.fixtures.n
    out = np.zeros(len(keys), bool)
    # a pair skipped for sleeping has a sleeping dynamic body: without one (rain, a falling
    # pile) one compiled scan is all (a numpy mask cost rain1000 11 us a step)
    if not len(keys) or not nf or not any_asleep(F.awake, F.kind, nf):
        return out
    ids = F.id[:nf]
    top = int(ids.max())
    slot = np.full(top + 2, -1, np.int64)  # fixture id -> slot; top + 1: every id not alive
    slot[ids] = np.arange(nf)
    i = slot[np.minimum(keys >> 32, top + 1)]
    j = slot[np.minimum(keys & LOW, top + 1)]
    live = (i >= 0) & (j >= 0)
    i, j = np.where(live, i, 0), np.where(live, j, 0)
    ki, kj = F.kind[i], F.kind[j]
    si, sj = F.awake[i] == 0, F.awake[j] == 0  # asleep as the step's broad phase saw them
    moving = (ki == DYNAMIC) | (kj == DYNAMIC)  # no body of the pair can move: gone, not asleep
    return live & moving & ((si & sj) | (si & (kj == STATIC)) | (sj & (ki == STATIC)))
