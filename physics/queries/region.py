"""Fixtures whose box meets a region, by a walk down the query tree (its cost follows what it finds)."""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from ..store.fixtures import CIRCLE
from .filter import accepts
from .tree import COUNT, LEFT, RIGHT, START, boxes_meet


@kernel(runtime=True)
def box_candidates(F, box, nb, info, order, x0, y0, x1, y1, category, mask, out):
    """Slots (into ``out``) of fixtures passing the filter whose exact box meets (x0, y0)-(x1, y1)."""
    if order.shape[0] == 0:
        return 0
    stack = np.empty(128, np.int32)
    stack[0] = 0
    top = 1
    m = 0
    while top > 0:
        top -= 1
        k = stack[top]
        if not boxes_meet(nb, k, x0, y0, x1, y1):
            continue
        if info[k, COUNT] < 0:
            stack[top] = info[k, LEFT]
            stack[top + 1] = info[k, RIGHT]
            top += 2
            continue
        for j in range(info[k, START], info[k, START] + info[k, COUNT]):
            f = order[j]
            if accepts(F, f, category, mask) and boxes_meet(box, f, x0, y0, x1, y1):
                out[m] = f
                m += 1
    return m


@kernel(runtime=True, forceinline=True)
def core_of(F, wv, wc, f):
    """Fixture f's world core as a (k, 2) view: its centre for a circle, else its vertices."""
    if F.shape[f] == CIRCLE:
        return wc[f:f + 1]
    a = F.vstart[f]
    return wv[a:a + F.vcount[f]]
