"""The broad phase of a world that mostly rests: a few awake boxes queried against a sorted
index of the resting ones.

With at most FEW_AWAKE boxes not resting (asleep or static), every pair has one of them
(filter.can_pair), so the sweep's pairs are the awake boxes' overlaps.  The resting boxes do not
move, so their boxes sorted by their lower x edge are an index that stays valid until one of
them wakes, sleeps or is edited: an awake box's partners lie in the run of keys between its own
lower edge minus the widest resting box and its upper edge (two binary searches), as in the
static tree Box2D v3 keeps for its sleeping and static proxies (broad_phase.c).  The step
rebuilds the index only when the resting set changed (step/active.py counts the changes).
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel
from ..argsort import argsort_into, first_at_least
from .filter import can_pair, overlap, push
from .sweep import FEW_AWAKE, _finite, _resting

#: relative slack on the widest resting box: its width rounds differently from its two edges
SLACK = 1e-12


@kernel
def few_awake_of(F, actf, nactf):
    """Whether at most FEW_AWAKE of the ``nactf`` fixtures listed in ``actf`` (every fixture that
    can be awake: step/active.py) are not resting."""
    m = 0
    for k in range(nactf):
        if not _resting(F.kind, F.awake, actf[k]):
            m += 1
            if m > FEW_AWAKE:
                return False
    return True


@kernel
def build_index(F, nf, skey, order, tmp, rkey, rslot):
    """The resting fixtures with finite boxes, sorted by their lower x edge: keys into ``rkey``,
    fixtures into ``rslot`` (``skey``, ``order``, ``tmp``: scratch, nf long).  Returns their count
    and the widest one's width along x."""
    m = 0
    wide = 0.0
    for f in range(nf):
        if _resting(F.kind, F.awake, f) and _finite(F.aabb, f):
            skey[m] = F.aabb[f, 0]
            tmp[m] = f
            wide = max(wide, F.aabb[f, 2] - F.aabb[f, 0])
            m += 1
    for k in range(m):
        rslot[k] = tmp[k]
    argsort_into(skey, m, order, tmp)
    for k in range(m):
        rkey[k] = skey[order[k]]
        tmp[k] = rslot[order[k]]
    for k in range(m):
        rslot[k] = tmp[k]
    return m, wide


@kernel
def indexed_pairs(F, actf, nactf, rkey, rslot, nrest, wide, tmp):
    """The pairs of the awake fixtures among the ``nactf`` in ``actf`` (slot order): with the
    resting ones the index finds, and with each other once; into ``tmp`` (as many as fit,
    filter.push).  Returns the count."""
    aabb = F.aabb
    kind = F.kind
    awake = F.awake
    k = np.int64(0)  # not a literal: push compiles once
    reach = wide * (1.0 + SLACK)
    for a in range(nactf):
        i = actf[a]
        if _resting(kind, awake, i) or not _finite(aabb, i):
            continue
        hi = aabb[i, 2]
        lo = aabb[i, 0] - reach
        for c in range(first_at_least(rkey, nrest, lo - SLACK * abs(lo)), nrest):
            if rkey[c] > hi:
                break
            j = rslot[c]
            if overlap(aabb, i, j) and can_pair(kind, awake, i, j):
                k = push(tmp, k, i, j)
        for b in range(a + 1, nactf):
            j = actf[b]
            if _resting(kind, awake, j) or not _finite(aabb, j):
                continue
            if overlap(aabb, i, j) and can_pair(kind, awake, i, j):
                k = push(tmp, k, i, j)
    return k
