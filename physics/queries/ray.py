"""Ray casts over the query tree: every hit of one ray, its nearest hit, or the nearest hit of many rays."""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel
from .filter import accepts
from .ray_shapes import ray_fixture
from .tree import COUNT, LEFT, RIGHT, START, ray_enters


@kernel(entry=True, runtime=True)
def cast_one(F, wv, wn, wc, nb, info, order, px, py, dx, dy, first, category, mask, slots, ts, ns):
    """Hits of the ray p + t d (t in [0, 1]) into slots/ts/ns; returns their count.

    With ``first`` only the nearest is kept and the ray is shortened to it as the walk goes,
    so boxes behind it are never opened (nearer child first).  A tie keeps the lower slot.
    """
    if order.shape[0] == 0:
        return 0
    stack = np.empty(128, np.int32)
    stack[0] = 0
    top = 1
    m = 0
    tmax = 1.0
    while top > 0:
        top -= 1
        k = stack[top]
        if ray_enters(nb, k, px, py, dx, dy, tmax) == math.inf:
            continue
        if info[k, COUNT] < 0:
            a = info[k, LEFT]
            b = info[k, RIGHT]
            ta = ray_enters(nb, a, px, py, dx, dy, tmax)
            tb = ray_enters(nb, b, px, py, dx, dy, tmax)
            if ta < tb:  # the nearer child is popped first
                a, b = b, a
            stack[top] = a
            stack[top + 1] = b
            top += 2
            continue
        for j in range(info[k, START], info[k, START] + info[k, COUNT]):
            f = order[j]
            if not accepts(F, f, category, mask):
                continue
            t, nx, ny = ray_fixture(F, wv, wn, wc, f, px, py, dx, dy)
            if t < 0.0 or t > tmax:
                continue
            if first:
                if m == 1 and (t > ts[0] or (t == ts[0] and f > slots[0])):
                    continue
                tmax = t
                m = 1
                slots[0] = f
                ts[0] = t
                ns[0, 0] = nx
                ns[0, 1] = ny
            else:
                slots[m] = f
                ts[m] = t
                ns[m, 0] = nx
                ns[m, 1] = ny
                m += 1
    return m


@kernel(entry=True, runtime=True)
def cast_many(F, wv, wn, wc, nb, info, order, starts, ends, category, mask, slot, t, normal):
    """The nearest hit of each ray starts[i] -> ends[i] (slot -1 and t -1 for a miss)."""
    one = np.empty(1, np.int32)
    ot = np.empty(1)
    on = np.empty((1, 2))
    for i in range(starts.shape[0]):
        px = starts[i, 0]
        py = starts[i, 1]
        m = cast_one(F, wv, wn, wc, nb, info, order, px, py, ends[i, 0] - px, ends[i, 1] - py, True,
                     category, mask, one, ot, on)
        if m == 0:
            slot[i] = -1
            t[i] = -1.0
            normal[i, 0] = 0.0
            normal[i, 1] = 0.0
        else:
            slot[i] = one[0]
            t[i] = ot[0]
            normal[i, 0] = on[0, 0]
            normal[i, 1] = on[0, 1]
