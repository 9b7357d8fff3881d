"""The structure of the global system, rebuilt only when the joints or their bodies change.

From the joint table: which rows (every equality row of a joint with a moving
body), in which order, the pattern of the upper triangle of J M^-1 J^T by
compressed columns, each entry's contributions (one per shared moving body,
see solve.py), and the symbolic factorisation (ldl.symbolic).  Joints are
grouped by the moving bodies they share (components); each component is
ordered by minimum degree on its joint graph, and one whose elimination would
create more fill than FILL_BUDGET per joint stays with the sequential rows
(``seq``): a cloth-like grid of joints factorises with fill that grows faster
than its size, while trees create none.
"""
from __future__ import annotations

import heapq
from collections import namedtuple

import numpy as np

from ....store import DYNAMIC
from ..prepare import equality_counts
from . import ldl

FILL_BUDGET = 6  # fill-in (matrix entries) allowed per joint of a component, plus FILL_SLACK
FILL_SLACK = 64

JointSystem = namedtuple("JointSystem", "dims row_j row_r jrow Ap Ai Ax contrib Parent Lnz Lp Li Lx invD Y "
                                        "Pattern Flag x skip")


def _system(nrows, nnz, ncontrib, nnzl, jcap):
    i4 = np.int64
    return JointSystem(dims=np.array([nrows, ncontrib, nnz, nnzl], i4), row_j=np.zeros(nrows, i4),
                       row_r=np.zeros(nrows, i4), jrow=np.full(jcap, -1, i4), Ap=np.zeros(nrows + 1, i4),
                       Ai=np.zeros(nnz, i4), Ax=np.zeros(nnz), contrib=np.zeros((ncontrib, 8), i4),
                       Parent=np.zeros(nrows, i4), Lnz=np.zeros(nrows, i4), Lp=np.zeros(nrows + 1, i4),
                       Li=np.zeros(nnzl, i4), Lx=np.zeros(nnzl), invD=np.zeros(nrows), Y=np.zeros(nrows),
                       Pattern=np.zeros(nrows, i4), Flag=np.zeros(nrows, i4), x=np.zeros(nrows),
                       skip=np.zeros(nrows, np.bool_))


def empty_system(jcap: int) -> JointSystem:
    return _system(0, 0, 0, 0, jcap)


def _moving_bodies(J, nj, kinds, m):
    """Per joint with equality rows, the slots of its dynamic bodies (and on which side)."""
    out = {}
    for j in range(nj):
        if m[j] == 0:
            continue
        ends = [(int(J.a[j]), 1)]
        if J.b[j] >= 0:
            ends.append((int(J.b[j]), -1))
        ends = [(c, s) for c, s in ends if kinds[c] == DYNAMIC]
        if ends:
            out[j] = ends
    return out


def _components(moving):
    """Joints grouped by shared dynamic bodies (union-find), in joint order."""
    parent = {j: j for j in moving}

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    first = {}
    for j, ends in moving.items():
        for c, _ in ends:
            if c in first:
                ra, rb = find(first[c]), find(j)
                if ra != rb:
                    parent[max(ra, rb)] = min(ra, rb)
            else:
                first[c] = j
    groups = {}
    for j in moving:
        groups.setdefault(find(j), []).append(j)
    return list(groups.values())


def _adjacency(joints, moving):
    by_body = {}
    for j in joints:
        for c, _ in moving[j]:
            by_body.setdefault(c, []).append(j)
    adj = {j: set() for j in joints}
    for inc in by_body.values():
        for j in inc:
            adj[j].update(inc)
    for j in joints:
        adj[j].discard(j)
    return adj


def minimum_degree(joints, adj, budget):
    """Elimination order by minimum degree (ties: lowest joint), or None past ``budget`` fill."""
    adj = {j: set(s) for j, s in adj.items()}
    heap = [(len(adj[j]), j) for j in joints]
    heapq.heapify(heap)
    order, fill = [], 0
    while heap:
        d, v = heapq.heappop(heap)
        if v not in adj or d != len(adj[v]):
            continue  # eliminated already, or a stale degree
        nb = adj.pop(v)
        order.append(v)
        for u in nb:
            au = adj[u]
            au.discard(v)
            before = len(au)
            au |= nb
            au.discard(u)
            fill += len(au) - before
            heapq.heappush(heap, (len(au), u))
        if fill > budget:
            return None
    return order


def build(J, nj: int, kinds: np.ndarray, jcap: int):
    """(JointSystem, seq): the global system for the joints, and which joints stay sequential."""
    m = np.zeros(max(nj, 1), np.int64)
    if nj:
        equality_counts(J, nj, m)
    seq = np.zeros(jcap, np.int8)
    moving = _moving_bodies(J, nj, kinds, m)
    rows, order = [], []
    for comp in _components(moving):
        adj = _adjacency(comp, moving)
        elim = minimum_degree(comp, adj, FILL_BUDGET * len(comp) + FILL_SLACK) if len(comp) > 1 else comp
        if elim is None:
            seq[comp] = 1
            continue
        order += elim
    system = _numbering(J, order, m, moving, jcap)
    return system, seq


def _numbering(J, order, m, moving, jcap):
    """Rows in elimination order, the upper pattern by columns, contributions, symbolic factor."""
    jrow = np.full(jcap, -1, np.int64)
    row_j, row_r = [], []
    for j in order:
        jrow[j] = len(row_j)
        for r in range(int(m[j])):
            row_j.append(j)
            row_r.append(r)
    nrows = len(row_j)
    if nrows == 0:
        return empty_system(jcap)
    entries, contrib = {}, []
    by_body = {}
    for j in order:
        for c, side in moving[j]:
            by_body.setdefault(c, []).append((j, side))
    for c, inc in by_body.items():
        for j, sj in inc:
            for k, sk in inc:
                if jrow[j] > jrow[k]:
                    continue
                for r in range(int(m[j])):
                    for s in range(int(m[k])):
                        i, col = jrow[j] + r, jrow[k] + s
                        if i > col:
                            continue
                        e = entries.setdefault((col, i), len(entries))
                        contrib.append((e, c, j, r, sj, k, s, sk))
    keys = sorted(entries)
    index = np.zeros(len(keys), np.int64)
    for new, key in enumerate(keys):
        index[entries[key]] = new
    sys = _system(nrows, len(keys), len(contrib), 0, jcap)
    sys.jrow[:] = jrow
    sys.row_j[:] = row_j
    sys.row_r[:] = row_r
    cols = np.array([k[0] for k in keys], np.int64)
    sys.Ai[:] = [k[1] for k in keys]
    sys.Ap[1:] = np.cumsum(np.bincount(cols, minlength=nrows))
    q = np.array(contrib, np.int64)
    q[:, 0] = index[q[:, 0]]
    sys.contrib[:] = q
    ldl.symbolic(nrows, sys.Ap, sys.Ai, sys.Parent, sys.Lnz, sys.Flag, sys.Lp)
    nnzl = int(sys.Lp[nrows])
    return sys._replace(Li=np.zeros(max(nnzl, 1), np.int64), Lx=np.zeros(max(nnzl, 1)),
                        dims=np.array([nrows, len(contrib), len(keys), nnzl], np.int64))
