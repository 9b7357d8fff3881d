"""Region quadtree over AABBs (seed report, section 4.2.2), rebuilt every call.

A node holding more than ``LEAF_SIZE`` boxes splits into four quadrants at the
centre of its boxes' extent (clipped to the node), so clustered or far-flung
scenes still split evenly; a box goes into every quadrant it touches.  Pairs
are tested only inside leaves, and a pair is reported only by the leaf whose
half-open region holds the lower-left corner of the pair's overlap, so a pair
seen in several leaves counts once (Ericson, "Real-Time Collision Detection",
7.3: the same de-duplication rule for objects stored in several cells).

Boxes are routed left when lo_x < split and right when hi_x >= split; the
overlap corner of two boxes in a node then always lands in a child holding
both.  A split that leaves some child with every box of its parent (identical
or all-covering boxes) cannot help, so the node stays a leaf.
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel
from .filter import can_pair, overlap, push
from .order import sort_pairs

LEAF_SIZE = 32
MAX_DEPTH = 24
# node info columns
START, COUNT, DEPTH = 0, 1, 2


@kernel
def _grow(a, need):
    if need <= a.shape[0]:
        return a
    b = np.empty((max(need, 2 * a.shape[0]),) + a.shape[1:], a.dtype)
    b[: a.shape[0]] = a
    return b


@kernel
def _split_point(aabb, items, s, c, reg):
    ux0 = math.inf
    uy0 = math.inf
    ux1 = -math.inf
    uy1 = -math.inf
    for a in range(s, s + c):
        i = items[a]
        ux0 = min(ux0, aabb[i, 0])
        uy0 = min(uy0, aabb[i, 1])
        ux1 = max(ux1, aabb[i, 2])
        uy1 = max(uy1, aabb[i, 3])
    ux0 = max(ux0, reg[0])
    uy0 = max(uy0, reg[1])
    ux1 = min(ux1, reg[2])
    uy1 = min(uy1, reg[3])
    return 0.5 * (ux0 + ux1), 0.5 * (uy0 + uy1)


@kernel
def _quadrant_counts(aabb, items, s, c, sx, sy):
    """Boxes per child (0 left-bottom, 1 right-bottom, 2 left-top, 3 right-top)."""
    c0 = c1 = c2 = c3 = 0
    for a in range(s, s + c):
        i = items[a]
        left = aabb[i, 0] < sx
        right = aabb[i, 2] >= sx
        bottom = aabb[i, 1] < sy
        top = aabb[i, 3] >= sy
        c0 += left and bottom
        c1 += right and bottom
        c2 += left and top
        c3 += right and top
    return c0, c1, c2, c3


@kernel
def _leaf_pairs(B, items, s, c, reg, tmp, k):
    aabb = B.aabb
    for a in range(s, s + c):
        i = items[a]
        for b in range(a + 1, s + c):
            j = items[b]
            if not (overlap(aabb, i, j) and can_pair(B.kind, B.awake, i, j)):
                continue
            px = max(aabb[i, 0], aabb[j, 0])
            py = max(aabb[i, 1], aabb[j, 1])
            if reg[0] <= px < reg[2] and reg[1] <= py < reg[3]:
                k = push(tmp, k, i, j)
    return k


@kernel
def build(B, n, reg, info, items, tmp, emit):
    """Build the tree (and, when ``emit``, collect pairs into ``tmp``).

    Returns (pair count, node count, reg, info, items): the scratch arrays
    come back grown when the tree needed more room.
    """
    aabb = B.aabb
    m = 0
    items = _grow(items, n)
    for i in range(n):
        if (math.isfinite(aabb[i, 0]) and math.isfinite(aabb[i, 1])
                and math.isfinite(aabb[i, 2]) and math.isfinite(aabb[i, 3])):
            items[m] = i
            m += 1
    reg = _grow(reg, 1)
    info = _grow(info, 1)
    reg[0, 0] = -math.inf
    reg[0, 1] = -math.inf
    reg[0, 2] = math.inf
    reg[0, 3] = math.inf
    info[0, START] = 0
    info[0, COUNT] = m
    info[0, DEPTH] = 0
    nodes = 1
    top = m
    k = 0
    node = 0
    while node < nodes:  # breadth first: children are appended behind
        s = info[node, START]
        c = info[node, COUNT]
        leaf = c <= LEAF_SIZE or info[node, DEPTH] >= MAX_DEPTH
        sx = sy = 0.0
        counts = (0, 0, 0, 0)
        if not leaf:
            sx, sy = _split_point(aabb, items, s, c, reg[node])
            counts = _quadrant_counts(aabb, items, s, c, sx, sy)
            leaf = max(counts) >= c
        if leaf:
            if emit:
                k = _leaf_pairs(B, items, s, c, reg[node], tmp, k)
            node += 1
            continue
        items = _grow(items, top + counts[0] + counts[1] + counts[2] + counts[3])
        reg = _grow(reg, nodes + 4)
        info = _grow(info, nodes + 4)
        r0, r1, r2, r3 = reg[node, 0], reg[node, 1], reg[node, 2], reg[node, 3]
        for q in range(4):
            if counts[q] == 0:
                continue
            right = q & 1
            upper = q >> 1
            reg[nodes, 0] = sx if right else r0
            reg[nodes, 2] = r2 if right else sx
            reg[nodes, 1] = sy if upper else r1
            reg[nodes, 3] = r3 if upper else sy
            info[nodes, START] = top
            info[nodes, DEPTH] = info[node, DEPTH] + 1
            for a in range(s, s + c):
                i = items[a]
                inx = aabb[i, 2] >= sx if right else aabb[i, 0] < sx
                iny = aabb[i, 3] >= sy if upper else aabb[i, 1] < sy
                if inx and iny:
                    items[top] = i
                    top += 1
            info[nodes, COUNT] = top - info[nodes, START]
            nodes += 1
        node += 1
    return k, nodes, reg, info, items


@kernel
def quadtree_pairs(B, n, reg, info, items, tmp, head, pairs):
    """Pairs sorted by (i, j); returns (count, reg, info, items) like ``build``."""
    k, _, reg, info, items = build(B, n, reg, info, items, tmp, True)
    if k <= tmp.shape[0] and k <= pairs.shape[0]:
        sort_pairs(tmp, k, n, head, pairs)
    return k, reg, info, items
