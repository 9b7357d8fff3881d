"""Deterministic pair order: ascending (i, j), in linear time.

The solver visits contacts in the order the broad phase emits them, and
Gauss-Seidel results depend on that order; sorting makes every method (and
so the "auto" choice) give bit-identical simulations.  Two stable counting
sorts, by j and then by i (an LSD radix sort, Knuth, TAOCP vol. 3, 5.2.5),
cost O(count + n) whatever order the sweep emitted the pairs in; sorting
each i bucket by insertion instead was quadratic in the bucket, and a fast
body's fat box fills its bucket with partners in sweep order, not slot order.
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel


@kernel
def _count_by(src, count, n, head, col, dst):
    """src[:count] into dst[:count], stably ordered by column ``col`` (values below n)."""
    for s in range(n + 1):
        head[s] = 0
    for k in range(count):
        head[src[k, col] + 1] += 1
    for s in range(n):
        head[s + 1] += head[s]
    for k in range(count):
        v = src[k, col]
        d = head[v]
        head[v] = d + 1
        dst[d, 0] = src[k, 0]
        dst[d, 1] = src[k, 1]


@kernel
def sort_pairs(tmp, count, n, head, pairs):
    """Write tmp[:count] into pairs[:count] sorted by (i, j); tmp[:count] is overwritten.

    ``head`` is int32 scratch of at least n + 1 entries.  A few pairs among many boxes (a
    sleeping wall's awake edge) are sorted by insertion instead: count^2 / 4 comparisons at
    most, below the counting sorts' 4 n when count^2 <= 16 n.  Pairs are distinct, so both
    give the one ascending order.
    """
    if count * count <= 16 * n:
        _insertion(tmp, count, pairs)
        return
    _count_by(tmp, count, n, head, np.int64(1), pairs)  # not literals: _count_by compiles once
    _count_by(pairs, count, n, head, np.int64(0), tmp)
    for k in range(count):
        pairs[k, 0] = tmp[k, 0]
        pairs[k, 1] = tmp[k, 1]


@kernel
def _insertion(src, count, dst):
    """src[:count] into dst[:count], ascending by (i, j) (insertion sort)."""
    for k in range(count):
        i = src[k, 0]
        j = src[k, 1]
        d = k
        while d > 0 and (dst[d - 1, 0] > i or (dst[d - 1, 0] == i and dst[d - 1, 1] > j)):
            dst[d, 0] = dst[d - 1, 0]
            dst[d, 1] = dst[d - 1, 1]
            d -= 1
        dst[d, 0] = i
        dst[d, 1] = j
