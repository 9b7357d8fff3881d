"""Deterministic pair order: ascending (i, j), in linear time.

The solver visits contacts in the order the broad phase emits them, and
Gauss-Seidel results depend on that order; sorting makes every method (and
so the "auto" choice) give bit-identical simulations.  A counting sort on i
followed by insertion sort inside each i bucket (a few entries each) beats a
comparison sort of all pairs.
"""
from __future__ import annotations

from ..._jit import kernel


@kernel
def sort_pairs(tmp, count, n, head, pairs):
    """Write tmp[:count] into pairs[:count] sorted by (i, j).

    ``head`` is int32 scratch of at least n + 1 entries.
    """
    for s in range(n + 1):
        head[s] = 0
    for k in range(count):
        head[tmp[k, 0] + 1] += 1
    for s in range(n):
        head[s + 1] += head[s]
    for k in range(count):
        i = tmp[k, 0]
        dst = head[i]
        head[i] = dst + 1
        pairs[dst, 0] = i
        pairs[dst, 1] = tmp[k, 1]
    # head[i] now ends bucket i; buckets are consecutive from 0
    start = 0
    for s in range(n):
        end = head[s]
        for a in range(start + 1, end):
            j = pairs[a, 1]
            b = a - 1
            while b >= start and pairs[b, 1] > j:
                pairs[b + 1, 1] = pairs[b, 1]
                b -= 1
            pairs[b + 1, 1] = j
        start = end
