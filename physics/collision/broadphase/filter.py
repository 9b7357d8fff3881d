"""Which slot pairs may ever produce a contact, and the AABB overlap test.

Shared by every broad-phase method so that they all report the same set
(docs/internals.md, "One step", stage 2).
"""
from __future__ import annotations

from ..._jit import kernel
from ...store import DYNAMIC, STATIC


@kernel
def can_pair(kind, awake, i, j):
    """False for pairs the solver could never move apart.

    Neither dynamic: static and kinematic bodies never respond to contacts.
    Both asleep, or asleep against static: nothing can wake them from here
    (an awake body touching a sleeper wakes it in the islands stage).
    """
    ki = kind[i]
    kj = kind[j]
    if ki != DYNAMIC and kj != DYNAMIC:
        return False
    ai = awake[i]
    aj = awake[j]
    if ai == 0 and aj == 0:
        return False
    if (ai == 0 and kj == STATIC) or (aj == 0 and ki == STATIC):
        return False
    return True


@kernel
def overlap(aabb, i, j):
    """Closed-box overlap: touching boxes count (speculative contacts start there)."""
    return (aabb[i, 0] <= aabb[j, 2] and aabb[j, 0] <= aabb[i, 2]
            and aabb[i, 1] <= aabb[j, 3] and aabb[j, 1] <= aabb[i, 3])


@kernel
def push(tmp, k, i, j):
    """Store pair k as (min, max) if the buffer has room; the caller counts on."""
    if k < tmp.shape[0]:
        if i < j:
            tmp[k, 0] = i
            tmp[k, 1] = j
        else:
            tmp[k, 0] = j
            tmp[k, 1] = i
    return k + 1
