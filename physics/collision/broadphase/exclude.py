"""Pairs that never collide because a joint joins them (unless it asks for ``collide_connected``).

The joints' keys ``(min slot << 32) | max slot`` are kept sorted (constraints/
joints/work.py) and each broad-phase pair is looked up by bisection; only a
world with such joints runs this.
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel


@kernel
def drop_excluded(pairs, npairs, keys):
    """Compact ``pairs[:npairs]`` (i < j) to those whose key is not in ``keys``; returns the count."""
    m = keys.shape[0]
    k = 0
    for p in range(npairs):
        key = np.int64(pairs[p, 0]) * 4294967296 + np.int64(pairs[p, 1])
        lo = 0
        hi = m
        while lo < hi:
            mid = (lo + hi) // 2
            if keys[mid] < key:
                lo = mid + 1
            else:
                hi = mid
        if lo < m and keys[lo] == key:
            continue
        pairs[k, 0] = pairs[p, 0]
        pairs[k, 1] = pairs[p, 1]
        k += 1
    return k
