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

from ..._jit import kernel
from .filter import can_pair, overlap, push
from .order import sort_pairs

LEAF_SIZE = 32
MAX_DEPTH = 24
# node info columns
START, COUNT, DEPTH = 0, 1, 2


@kernel(runtime=True)
def _grow(a, need):
    if need <= a.shape[0]:
        return a
    b = np.empty((max(need, 2 * a.shape[0]),) + a.shape[1:], a.dtype)
    b[: a.shape[0]] = a
    return b


@kernel
def _split_point(box, s, c, reg):
    ux0 = math.inf
    uy0 = math.inf
    ux1 = -math.inf
    uy1 = -math.inf
    for a in range(s, s + c):
        ux0 = min(ux0, box[a, 0])
        uy0 = min(uy0, box[a, 1])
        ux1 = max(ux1, box[a, 2])
        uy1 = max(uy1, box[a, 3])
    ux0 = max(ux0, reg[0])
    uy0 = max(uy0, reg[1])
    ux1 = min(ux1, reg[2])
    uy1 = min(uy1, reg[3])
    return 0.5 * (ux0 + ux1), 0.5 * (uy0 + uy1)


@kernel
def _quadrant_counts(box, s, c, sx, sy):
    """Boxes per child (0 left-bottom, 1 right-bottom, 2 left-top, 3 right-top)."""
    c0 = c1 = c2 = c3 = 0
    for a in range(s, s + c):
        left = box[a, 0] < sx
        right = box[a, 2] >= sx
        bottom = box[a, 1] < sy
        top = box[a, 3] >= sy
        c0 += left and bottom
        c1 += right and bottom
        c2 += left and top
        c3 += right and top
    return c0, c1, c2, c3


@kernel
def _leaf_pairs(B, items, box, s, c, reg, tmp, k):
    for a in range(s, s + c):
        i = items[a]
        for b in range(a + 1, s + c):
            if not overlap(box, a, b):
                continue
            j = items[b]
            if not can_pair(B.kind, B.awake, i, j):
                continue
            px = max(box[a, 0], box[b, 0])
            py = max(box[a, 1], box[b, 1])
            if reg[0] <= px < reg[2] and reg[1] <= py < reg[3]:
                k = push(tmp, k, i, j)
    return k


@kernel(entry=True, runtime=True)
def build(B, n, reg, info, items, box, tmp, emit):
    """Build the tree (and, when ``emit``, collect pairs into ``tmp``).

    Returns (pair count, node count, reg, info, items, box): the scratch
    arrays come back grown when the tree needed more room.  Each entry of
    ``items`` carries a copy of its box in ``box`` so that every pass over a
    node reads memory in order (random slot order cost 3x at 10k bodies).
    """
    aabb = B.aabb
    m = 0
    items = _grow(items, n)
    box = _grow(box, n)
    for i in range(n):
        if (math.isfinite(aabb[i, 0]) and math.isfinite(aabb[i, 1])
                and math.isfinite(aabb[i, 2]) and math.isfinite(aabb[i, 3])):
            items[m] = i
            for d in range(4):
                box[m, d] = aabb[i, d]
            m += 1
    one = np.int64(1)  # not a literal 1: _grow compiles once
    reg = _grow(reg, one)
    info = _grow(info, one)
    reg[0, 0] = -math.inf
    reg[0, 1] = -math.inf
    reg[0, 2] = math.inf
    reg[0, 3] = math.inf
    info[0, START] = 0
    info[0, COUNT] = m
    info[0, DEPTH] = 0
    nodes = 1
    top = m
    k = np.int64(0)  # not a literal: push compiles once
    node = 0
    while node < nodes:  # breadth first: children are appended behind
        s = info[node, START]
        c = info[node, COUNT]
        leaf = c <= LEAF_SIZE or info[node, DEPTH] >= MAX_DEPTH
        sx = sy = 0.0
        counts = (0, 0, 0, 0)
        if not leaf:
            sx, sy = _split_point(box, s, c, reg[node])
            counts = _quadrant_counts(box, s, c, sx, sy)
            leaf = max(counts) >= c
        if leaf:
            if emit:
                k = _leaf_pairs(B, items, box, s, c, reg[node], tmp, k)
            node += 1
            continue
        need = top + counts[0] + counts[1] + counts[2] + counts[3]
        items = _grow(items, need)
        box = _grow(box, need)
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
                inx = box[a, 2] >= sx if right else box[a, 0] < sx
                iny = box[a, 3] >= sy if upper else box[a, 1] < sy
                if inx and iny:
                    items[top] = items[a]
                    for d in range(4):
                        box[top, d] = box[a, d]
                    top += 1
            info[nodes, COUNT] = top - info[nodes, START]
            nodes += 1
        node += 1
    return k, nodes, reg, info, items, box


@kernel(entry=True, runtime=True)
def quadtree_pairs(B, n, reg, info, items, box, tmp, head, pairs):
    """Pairs sorted by (i, j); returns (count, reg, info, items, box) like ``build``."""
    k, _, reg, info, items, box = build(B, n, reg, info, items, box, tmp, np.bool_(True))
    if k <= tmp.shape[0] and k <= pairs.shape[0]:
        sort_pairs(tmp, k, n, head, pairs)
    return k, reg, info, items, box
