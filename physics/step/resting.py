"""Pairs that left the step's pairs only because they sleep: their touching or overlap goes on.

The broad phase skips a pair the solver could not move (collision/broadphase/filter.py
``can_pair``: both asleep, or asleep against static).  A contact or sensor overlap of such a
pair has not ended; the event trackers keep it (Box2D keeps a sleeping island's contacts too).
"""
from __future__ import annotations

import numpy as np

from ..store import DYNAMIC, STATIC

LOW = 0xFFFFFFFF


def _resting(F, i, j) -> bool:
    ki, kj = int(F.kind[i]), int(F.kind[j])
    if ki != DYNAMIC and kj != DYNAMIC:
        return False  # no body of the pair can move: the pair is gone, not asleep
    ai, aj = int(F.awake[i]), int(F.awake[j])
    return (ai == 0 and aj == 0) or (ai == 0 and kj == STATIC) or (aj == 0 and ki == STATIC)


def kept(world, keys: np.ndarray) -> np.ndarray:
    """For each fixture-pair key (id << 32 | id) that left this step's pairs: True when both
    fixtures live and the pair was skipped for sleeping (F.kind/F.awake as the step's broad
    phase saw them)."""
    slot_of = world._store.fixtures.slot_of
    F = world._store.fixtures.view
    out = np.zeros(len(keys), bool)
    for k, key in enumerate(keys.tolist()):
        i, j = slot_of.get(key >> 32), slot_of.get(key & LOW)
        out[k] = i is not None and j is not None and _resting(F, i, j)
    return out
