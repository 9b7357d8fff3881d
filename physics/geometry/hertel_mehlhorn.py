"""Hertel-Mehlhorn merging: triangles of a simple polygon into convex pieces, in O(n log n).

Hertel and Mehlhorn ("Fast triangulation of simple polygons", FCT 1983): remove each
diagonal of a triangulation whose removal leaves a convex piece.  A removal only widens the
angles at the diagonal's ends, so a diagonal refused once stays refused: one pass over the
diagonals, in any order, is the whole algorithm.  Every diagonal kept is essential at a
reflex vertex, and a reflex vertex keeps at most two, so there are at most 2r + 1 pieces for
r reflex vertices (at most four times the optimum).

The order changes which pieces come out, not the bound: the longest diagonals go first,
which merges the thin slivers an ear-clipping triangulation makes into fuller pieces (the
sort is the O(n log n); each removal is O(1) on half-edges, whose next links are respliced,
and a union-find counts each piece's vertices against the cap).
"""
from __future__ import annotations

import math


def turn(p, a: int, b: int, c: int) -> float:
    """Sine of the turn at b along a -> b -> c (> 0: left, convex for a CCW outline)."""
    e0x, e0y = p[b][0] - p[a][0], p[b][1] - p[a][1]
    e1x, e1y = p[c][0] - p[b][0], p[c][1] - p[b][1]
    norm = math.hypot(e0x, e0y) * math.hypot(e1x, e1y)
    return (e0x * e1y - e0y * e1x) / norm if norm > 0.0 else 0.0  # a point visited twice: no turn


def merge(p, triangles, max_vertices: int, straight: float) -> list[list[int]]:
    """Convex pieces (CCW vertex index cycles) from CCW ``triangles`` of the polygon with points
    ``p``; a merge must keep every turn above ``straight`` and at most ``max_vertices`` vertices."""
    origin, dest, nxt, face = [], [], [], []
    twin_of = {}
    for f, (a, b, c) in enumerate(triangles):
        h = len(origin)
        for u, v in ((a, b), (b, c), (c, a)):
            twin_of[(u, v)] = len(origin)
            origin.append(u)
            dest.append(v)
            face.append(f)
        nxt += [h + 1, h + 2, h]
    prv = [0] * len(nxt)
    for h, g in enumerate(nxt):
        prv[g] = h
    diagonals = [(h, twin_of[(dest[h], origin[h])]) for h in range(len(origin))
                 if origin[h] < dest[h] and (dest[h], origin[h]) in twin_of]
    diagonals.sort(key=lambda d: -math.dist(p[origin[d[0]]], p[dest[d[0]]]))
    parent = list(range(len(triangles)))
    size = [3] * len(triangles)
    removed = [False] * len(origin)

    def find(f):
        while parent[f] != f:
            parent[f] = parent[parent[f]]
            f = parent[f]
        return f

    for h, g in diagonals:  # h: u -> v in piece P, g: v -> u in piece Q
        fp, fq = find(face[h]), find(face[g])
        if size[fp] + size[fq] - 2 > max_vertices:
            continue
        u, v = origin[h], dest[h]
        if turn(p, origin[prv[h]], u, dest[nxt[g]]) <= straight or turn(p, origin[prv[g]], v, dest[nxt[h]]) <= straight:
            continue
        nxt[prv[h]], prv[nxt[g]] = nxt[g], prv[h]
        nxt[prv[g]], prv[nxt[h]] = nxt[h], prv[g]
        removed[h] = removed[g] = True
        parent[fq] = fp
        size[fp] += size[fq] - 2
    return _cycles(origin, nxt, removed)


def _cycles(origin, nxt, removed) -> list[list[int]]:
    seen = list(removed)
    out = []
    for h in range(len(origin)):
        if seen[h]:
            continue
        cyc = []
        while not seen[h]:
            seen[h] = True
            cyc.append(origin[h])
            h = nxt[h]
        out.append(cyc)
    return out
