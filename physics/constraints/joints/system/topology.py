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

import numpy as np

from ....store import DYNAMIC
from ....store.segments import FLOAT, INT, segments_class
from ..prepare import equality_counts
from . import ldl
from .block import BLOCK, SEQUENTIAL

FILL_BUDGET = 6  # fill-in (matrix entries) allowed per joint of a component, plus FILL_SLACK
FILL_SLACK = 64
LONE_AS_BLOCK = [True]  # (False: lone joints go into the system; tests compare the two)

#: ``dims``: the rows, contributions, matrix entries and L's entries, and whether L and invD hold
#: the factors of the velocity passes' matrix at the rows' current geometry (solve.py: FACTORED)
DIMS = 5
#: the system's arrays (store/segments.py: two buffers, so a kernel call passes two arrays, not 19):
#: integers or floats, and a row width for the 2-D contributions
JointSystem = segments_class("JointSystem", {
    "dims": (INT, 0), "row_j": (INT, 0), "row_r": (INT, 0), "jrow": (INT, 0), "Ap": (INT, 0), "Ai": (INT, 0),
    "Ax": (FLOAT, 0), "contrib": (INT, 8), "Parent": (INT, 0), "Lnz": (INT, 0), "Lp": (INT, 0), "Li": (INT, 0),
    "Lx": (FLOAT, 0), "invD": (FLOAT, 0), "Y": (FLOAT, 0), "Pattern": (INT, 0), "Flag": (INT, 0), "x": (FLOAT, 0),
    "skip": (INT, 0), "gam": (FLOAT, 0)}, "joint_system")
#: the fields that describe the system's structure (the rest is the passes' scratch)
STRUCTURE = ("jrow", "row_j", "row_r", "Ai", "Ap", "contrib", "Parent", "Lnz", "Flag", "Lp")


def _system(nrows, nnz, ncontrib, nnzl, jcap):
    r = nrows
    sys = JointSystem(dims=DIMS, row_j=r, row_r=r, jrow=jcap, Ap=r + 1, Ai=nnz, Ax=nnz, contrib=ncontrib, Parent=r,
                      Lnz=r, Lp=r + 1, Li=max(nnzl, 1), Lx=max(nnzl, 1), invD=r, Y=r, Pattern=r, Flag=r, x=r, skip=r,
                      gam=r)
    sys.dims[:] = (nrows, ncontrib, nnz, nnzl, 0)
    sys.jrow[:] = -1
    return sys


def empty_system(jcap: int) -> JointSystem:
    return _system(0, 0, 0, 0, jcap)


def _moving_bodies(J, nj, kinds, m, lo=0):
    """Per joint lo..nj-1 with equality rows, the slots of its dynamic bodies (and on which
    side).  Over Python lists: indexing numpy arrays one element at a time cost ~10 us a joint."""
    a, b, mm = J.a[lo:nj].tolist(), J.b[lo:nj].tolist(), m[lo:nj].tolist()
    dyn = (np.asarray(kinds) == DYNAMIC).tolist()
    out = {}
    for i in range(nj - lo):
        if mm[i] == 0:
            continue
        ends = [(a[i], 1)] if dyn[a[i]] else []
        if b[i] >= 0 and dyn[b[i]]:
            ends.append((b[i], -1))
        if ends:
            out[lo + i] = ends
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


#: elimination orders by a component's shape (``_shape``), in its own numbering: a scene made of
#: many copies of one rig (a rain of ragdolls) orders the rig once, not at every rebuild
_ORDERS: dict = {}
_ORDERS_MAX = 4096


def _shape(comp, moving):
    """A component's joints as the local numbers of the bodies they move (numbered as first met):
    equal shapes have equal joint graphs under the numbering that keeps the joints' order."""
    local = {}
    return tuple(tuple(local.setdefault(c, len(local)) for c, _ in moving[j]) for j in comp)


def _elimination(comp, moving):
    """``minimum_degree`` of one component (``comp`` in ascending joint order), remembered by its
    shape: minimum degree breaks ties by the lower joint, and numbering the joints 0..k-1 in
    ascending order keeps every comparison, so the order found once serves every copy."""
    key = _shape(comp, moving)
    local = _ORDERS.get(key, False)
    if local is False:
        index = list(range(len(comp)))
        adj = _adjacency(index, {i: [(c, 0) for c in ends] for i, ends in enumerate(key)})
        local = minimum_degree(index, adj, FILL_BUDGET * len(comp) + FILL_SLACK)
        if len(_ORDERS) >= _ORDERS_MAX:
            _ORDERS.clear()
        _ORDERS[key] = local
    return None if local is None else [comp[i] for i in local]


def build(J, nj: int, kinds: np.ndarray, jcap: int, lo: int = 0):
    """(JointSystem, seq): the global system for joints lo..nj-1, and which of them stay out of
    it (SEQUENTIAL, BLOCK; ``seq`` has a place for every joint, those before lo 0)."""
    m = np.zeros(max(nj, 1), np.int64)
    if nj:
        equality_counts(J, nj, m)
    seq = np.zeros(jcap, np.int8)
    moving = _moving_bodies(J, nj, kinds, m, lo)
    order = []
    for comp in _components(moving):
        if len(comp) == 1 and LONE_AS_BLOCK[0]:
            seq[comp] = BLOCK
            continue
        elim = _elimination(comp, moving) if len(comp) > 1 else comp
        if elim is None:
            seq[comp] = SEQUENTIAL
            continue
        order += elim
    system = _numbering(J, order, m, moving, jcap)
    return system, seq


def _incidences(order, moving):
    """(body, joint, side) of every moving end in elimination order, grouped by body in the order
    bodies are first met (stable within a body): the order the contributions are listed in."""
    # one flat list of ints: numpy reads it faster than a list of tuples
    inc = np.array([x for j in order for c, side in moving[j] for x in (c, j, side)], np.int64).reshape(-1, 3)
    uniq, first, inv = np.unique(inc[:, 0], return_index=True, return_inverse=True)
    rank = np.empty(len(uniq), np.int64)
    rank[np.argsort(first)] = np.arange(len(uniq))
    g = rank[inv.reshape(-1)]
    return inc[np.argsort(g, kind="stable")], g


def _expand(counts):
    """(owner, index within owner) of ``counts[i]`` items per owner i, in owner order."""
    owner = np.repeat(np.arange(len(counts)), counts)
    start = np.cumsum(counts) - counts
    return owner, np.arange(len(owner)) - start[owner]


def _contributions(order, m, moving, jrow):
    """Per upper-triangle entry touched through a shared moving body: (col, i) and the contribution
    row (c, j, r, sj, k, s, sk), listed body by body, joint pairs (j, k) with jrow[j] <= jrow[k], then
    rows r of j and s of k with i = jrow[j] + r <= col = jrow[k] + s: numpy over the arrays (a Python
    loop here cost 0.2 s per rebuild for rain's 8,000 joints)."""
    inc, g = _incidences(order, moving)
    size = np.bincount(g)
    gs = np.sort(g)
    start = np.cumsum(size) - size
    u, off = _expand(size[gs])  # every ordered pair (u, v) of incidences of one body
    v = start[gs[u]] + off
    ju, jv = inc[u, 1], inc[v, 1]
    keep = jrow[ju] <= jrow[jv]
    u, v, ju, jv = u[keep], v[keep], ju[keep], jv[keep]
    p, t = _expand(m[ju] * m[jv])
    r, s = t // m[jv][p], t % m[jv][p]
    i, col = jrow[ju][p] + r, jrow[jv][p] + s
    keep = i <= col
    p, r, s, i, col = p[keep], r[keep], s[keep], i[keep], col[keep]
    rows = np.stack([inc[u[p], 0], ju[p], r, inc[u[p], 2], jv[p], s, inc[v[p], 2]], axis=1)
    return col, i, rows


def _numbering(J, order, m, moving, jcap):
    """Rows in elimination order, the upper pattern by columns, contributions, symbolic factor."""
    jrow = np.full(jcap, -1, np.int64)
    order = np.array(order, np.int64)
    mj = m[order].astype(np.int64)
    starts = np.cumsum(mj) - mj
    jrow[order] = starts
    nrows = int(mj.sum())
    if nrows == 0:
        return empty_system(jcap)
    m = m.astype(np.int64)
    col, i, rows = _contributions(order, m, moving, jrow)
    # entries sorted by (col, i); each contribution names its entry by that rank
    keys, entry = np.unique(col * nrows + i, return_inverse=True)
    sys = _system(nrows, len(keys), len(rows), 0, jcap)
    sys.jrow[:] = jrow
    sys.row_j[:] = np.repeat(order, mj)
    sys.row_r[:] = np.arange(nrows) - np.repeat(starts, mj)
    sys.Ai[:] = keys % nrows
    sys.Ap[1:] = np.cumsum(np.bincount(keys // nrows, minlength=nrows))
    sys.contrib[:, 0] = entry.reshape(-1)
    sys.contrib[:, 1:] = rows
    ldl.symbolic(nrows, sys.Ap, sys.Ai, sys.Parent, sys.Lnz, sys.Flag, sys.Lp)
    nnzl = int(sys.Lp[nrows])
    out = _system(nrows, len(keys), len(rows), nnzl, jcap)  # the same, with room for L's entries
    for name in STRUCTURE:
        getattr(out, name)[...] = getattr(sys, name)
    return out
