"""A bounding-volume hierarchy over the fixtures' boxes, built top-down by median splits.

Each node splits its boxes at the median centroid along the longer axis of the centroids'
extent (Ericson, "Real-Time Collision Detection", 6.2.1: median-cut top-down build), so the
tree is balanced (depth ~ log2 n) whatever the layout; leaves hold at most ``LEAF`` boxes.
Built once per cached query state (cache.py) in O(n log^2 n); a query then visits only the
nodes whose box meets its ray or region, so its cost follows what it finds, not the world.
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel

LEAF = 4
#: node columns of ``info``: first item, item count (leaf) or -1, left child, right child
START, COUNT, LEFT, RIGHT = 0, 1, 2, 3


@kernel(entry=True, runtime=True)
def build_tree(box, n):
    """(node boxes (m, 4), node info (m, 4), item order (n,)) for the first ``n`` rows of ``box``."""
    cap = max(2 * n, 1)
    nb = np.empty((cap, 4))
    info = np.full((cap, 4), -1, np.int32)
    order = np.arange(n).astype(np.int32)
    cx = 0.5 * (box[:n, 0] + box[:n, 2])
    cy = 0.5 * (box[:n, 1] + box[:n, 3])
    info[0, START] = 0
    info[0, COUNT] = n
    stack = np.empty(64, np.int32)
    stack[0] = 0
    top = 1
    m = 1
    while top > 0:
        top -= 1
        k = stack[top]
        s = info[k, START]
        e = s + info[k, COUNT]
        x0 = y0 = math.inf
        x1 = y1 = -math.inf
        ax0 = ay0 = math.inf
        ax1 = ay1 = -math.inf
        for a in range(s, e):
            j = order[a]
            x0 = min(x0, box[j, 0])
            y0 = min(y0, box[j, 1])
            x1 = max(x1, box[j, 2])
            y1 = max(y1, box[j, 3])
            ax0 = min(ax0, cx[j])
            ay0 = min(ay0, cy[j])
            ax1 = max(ax1, cx[j])
            ay1 = max(ay1, cy[j])
        nb[k, 0] = x0
        nb[k, 1] = y0
        nb[k, 2] = x1
        nb[k, 3] = y1
        if e - s <= LEAF:
            continue
        key = cx[order[s:e]] if ax1 - ax0 >= ay1 - ay0 else cy[order[s:e]]
        order[s:e] = order[s:e][np.argsort(key, kind="mergesort")]
        mid = (s + e) // 2
        info[k, COUNT] = -1
        info[k, LEFT] = m
        info[k, RIGHT] = m + 1
        info[m, START] = s
        info[m, COUNT] = mid - s
        info[m + 1, START] = mid
        info[m + 1, COUNT] = e - mid
        stack[top] = m
        stack[top + 1] = m + 1
        top += 2
        m += 2
    return nb[:m], info[:m], order


@kernel(forceinline=True)
def boxes_meet(nb, k, x0, y0, x1, y1):
    """Does node k's box overlap the box (x0, y0)-(x1, y1) (touching counts)?"""
    return nb[k, 0] <= x1 and x0 <= nb[k, 2] and nb[k, 1] <= y1 and y0 <= nb[k, 3]


@kernel(forceinline=True)
def ray_enters(nb, k, px, py, dx, dy, tmax):
    """Fraction where the ray p + t d enters node k's box (slab test), or inf if not in [0, tmax]."""
    lo = 0.0
    hi = tmax
    for ax in range(2):
        p = px if ax == 0 else py
        d = dx if ax == 0 else dy
        b0 = nb[k, ax]
        b1 = nb[k, ax + 2]
        if d == 0.0:
            if p < b0 or p > b1:
                return math.inf
            continue
        t0 = (b0 - p) / d
        t1 = (b1 - p) / d
        if t0 > t1:
            t0, t1 = t1, t0
        lo = max(lo, t0)
        hi = min(hi, t1)
        if lo > hi:
            return math.inf
    return lo
