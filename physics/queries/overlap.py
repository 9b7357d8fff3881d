"""Fixtures overlapping a rounded convex core placed in the world (box, point and shape queries).

A fixture overlaps when the distance between the two cores is at most the sum of the radii
(touching counts), which is exact for every shape (distance.py).
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from .distance import core_distance
from .region import box_candidates, core_of


@kernel(entry=True, runtime=True)
def overlapping(F, wv, wc, box, nb, info, order, P, rp, category, mask, out):
    """Slots (into ``out``, sorted) of the fixtures overlapping the core P grown by ``rp``; returns the count."""
    x0 = P[:, 0].min() - rp
    y0 = P[:, 1].min() - rp
    x1 = P[:, 0].max() + rp
    y1 = P[:, 1].max() + rp
    m = box_candidates(F, box, nb, info, order, x0, y0, x1, y1, category, mask, out)
    k = 0
    for j in range(m):
        f = out[j]
        d, _, _, _, _ = core_distance(P, core_of(F, wv, wc, f))
        if d <= rp + F.radius[f]:
            out[k] = f
            k += 1
    out[:k].sort()
    return k
