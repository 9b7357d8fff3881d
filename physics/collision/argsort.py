"""A stable argsort for the step's kernels: bottom-up merge sort over a key array.

numpy's ``np.argsort`` inside a kernel brings numba's generic quicksort and mergesort with it,
several CPU seconds of a cold compile for what a short merge sort does.  Being stable, this
gives exactly ``np.argsort(key[:n], kind="stable")``, NaN keys last as numpy puts them; for
distinct keys that is every sort's order.
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel


@kernel
def _before(key, i, j):
    """key[i] strictly before key[j] (a NaN after every number)."""
    a = key[i]
    b = key[j]
    return a < b or (math.isnan(b) and not math.isnan(a))


@kernel
def _merge_pass(key, src, dst, n, width):
    """Merge each pair of sorted runs of ``width`` in ``src`` into ``dst``."""
    for lo in range(0, n, 2 * width):
        mid = min(lo + width, n)
        hi = min(lo + 2 * width, n)
        i, j, k = lo, mid, lo
        while i < mid and j < hi:
            if _before(key, src[j], src[i]):  # the right run's first only when strictly before: stable
                dst[k] = src[j]
                j += 1
            else:
                dst[k] = src[i]
                i += 1
            k += 1
        while i < mid:
            dst[k] = src[i]
            i += 1
            k += 1
        while j < hi:
            dst[k] = src[j]
            j += 1
            k += 1


@kernel
def argsort_into(key, n, order, tmp):
    """The stable ascending order of ``key[:n]`` into ``order[:n]``; ``tmp``: n or more ints."""
    for i in range(n):
        order[i] = i
    in_tmp = False
    width = np.int64(1)  # not a literal 1: _merge_pass compiles once, not once more for it
    while width < n:
        if in_tmp:
            _merge_pass(key, tmp, order, n, width)
        else:
            _merge_pass(key, order, tmp, n, width)
        in_tmp = not in_tmp
        width *= 2
    if in_tmp:
        for i in range(n):
            order[i] = tmp[i]


@kernel(forceinline=True)
def first_at_least(key, m, x):
    """The first position in the ascending ``key[:m]`` whose key is not below x (m if none)."""
    lo = 0
    hi = m
    while lo < hi:
        mid = (lo + hi) // 2
        if key[mid] < x:
            lo = mid + 1
        else:
            hi = mid
    return lo
