"""All-pairs AABB test: the reference, and the fastest choice for small worlds.

Looping i < j emits pairs already in (i, j) order, so no sort is needed.
"""
from __future__ import annotations

from ..._jit import kernel
from ...store.flat import fixtures_view
from .filter import can_pair, overlap


@kernel(entry=True)
def brute_pairs(B, n, pairs):
    """Overlapping interacting pairs into ``pairs``; returns the total count
    (which may exceed the buffer: then only the first rows are written)."""
    aabb = B.aabb
    kind = B.kind
    awake = B.awake
    cap = pairs.shape[0]
    k = 0
    for i in range(n):
        for j in range(i + 1, n):
            if overlap(aabb, i, j) and can_pair(kind, awake, i, j):
                if k < cap:
                    pairs[k, 0] = i
                    pairs[k, 1] = j
                k += 1
    return k


@kernel(entry=True, runtime=True)
def brute_pairs_flat(FF, FI, ghost, wghost, n, pairs):
    """``brute_pairs`` over the fixture table's flat arrays (store/flat.py)."""
    return brute_pairs(fixtures_view(FF, FI, ghost, wghost), n, pairs)
