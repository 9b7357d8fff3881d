"""Impacts that pass along a row of touching bodies (Newton's cradle): propagated pair by pair.

The sub-step's solve treats every touching contact at once.  When a body strikes the first of
a row of touching bodies, the contact rows of the row all push in the same pass, so the blow
is shared out as if the row were one lump: the struck end and the middle move off together
and the bounce of the first contact (contact_restitution.py) cannot undo that (a five-disc
cradle at e = 1 kept 23 % of its swing energy after one impact).  A real row passes the blow
on as a wave: each contact, in turn, sees its neighbour arrive and bounces.

Here, for the bodies joined to a contact bouncing now by bouncy contacts (e >= ROW_RESTITUTION)
that pushed in this sub-step or touch (within the linear slop), the normal impulses the solve
gave those contacts are taken back, and the contacts are then resolved as impacts one pair at a
time, sweep after sweep, until none approaches: Guendelman, Bridson and Fedkiw's collision pass
("Nonconvex rigid bodies with stacking", SIGGRAPH 2003, sec. 5), with Newton's law
v_n' = -e v_n for an approach faster than the restitution threshold and an inelastic stop below.
Pairwise impacts at e <= 1 never add kinetic energy, so five equal discs pass the first one's
speed to the last and the middle stays still.  A lone bouncing pair keeps the manifold bounce
of contact_restitution.py (its 2x2 block bounce and its figures are unchanged).

The rows' impulses are taken back whole, a resting row's weight with them; the sweeps stop
what still approaches (the inelastic stop), so a row resting on the ground keeps its support
at the velocity level and its overlap is pushed out by the next sub-step's solve.  The
impulses the impact pass applies are not carried to the next sub-step's warm start (an impact
is not a load): those rows start it cold.  A cluster of more than MAX_ROW touching manifolds is
a pile, not a row, and contacts below ROW_RESTITUTION are not part of one: they keep the
solve's answer.
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from .body_rows import DCOS, DPX, DPY, DSIN, II, IM, VX, VY, W
from .contact_soft import BOUNCED, JN, MASS_N, NX, NY, PT, RNA, RNB, RTA, RTB, SEP0
from .restitution_cluster import _dynamic  # a body that moves (the clusters' test)

# manifolds in a row at most: the sweeps visit a row outward from the struck contact, but a
# branching row (a body touching three) may need up to one sweep per manifold, so the cost can
# grow as the square of the row; a larger cluster of touching bodies is a pile
MAX_ROW = 64
# the restitution of a row's contacts at least: below it a blow passed on pair by pair keeps
# little more than the solve's shared answer (each pair impact keeps (1 + e^2) / 2 of the pair's
# relative energy), while a struck resting pile of such bodies (a junk pile at e = 0.2-0.4) would
# lose its support impulses for the sub-step and settle later
ROW_RESTITUTION = 0.5


@kernel
def _touching(SB, C, R, k, slop):
    """Whether a point of manifold k pushed in this sub-step or is within ``slop`` of touching
    where the bodies are now (the separation of contact_soft.py's module doc)."""
    a = C.a[k]
    b = C.b[k]
    ddn = (SB[b, DPX] - SB[a, DPX]) * R[k, NX] + (SB[b, DPY] - SB[a, DPY]) * R[k, NY]
    for q in range(C.count[k]):
        o = q * PT
        if R[k, o + JN] > 0.0:
            return True
        sep = (R[k, o + SEP0] + ddn + (SB[b, DCOS] - 1.0) * R[k, o + RTB] + SB[b, DSIN] * R[k, o + RNB]
               - (SB[a, DCOS] - 1.0) * R[k, o + RTA] - SB[a, DSIN] * R[k, o + RNA])
        if sep <= slop:
            return True
    return False


@kernel
def _push(SB, a, b, nx, ny, rna, rnb, j):
    """Apply the normal impulse j (b pushed along n, a against it) at a point."""
    SB[a, VX] -= SB[a, IM] * j * nx
    SB[a, VY] -= SB[a, IM] * j * ny
    SB[a, W] -= SB[a, II] * j * rna
    SB[b, VX] += SB[b, IM] * j * nx
    SB[b, VY] += SB[b, IM] * j * ny
    SB[b, W] += SB[b, II] * j * rnb


@kernel(runtime=True)
def _adjacency(SB, C, nc, n):
    """(first, nxt): the bouncy manifolds (e >= ROW_RESTITUTION) at each dynamic body as linked
    lists: body i's first slot is first[i], slot s holds manifold s // 2, the next is nxt[s] (-1 ends)."""
    first = np.full(n, -1, dtype=np.int64)
    nxt = np.empty(2 * nc, dtype=np.int64)
    for k in range(nc):
        if C.e[k] >= ROW_RESTITUTION:
            for side in range(2):
                i = C.a[k] if side == 0 else C.b[k]
                if _dynamic(SB, i):
                    s = 2 * k + side
                    nxt[s] = first[i]
                    first[i] = s
    return first, nxt


@kernel(runtime=True)
def _rows(SB, C, R, nc, n, due, slop):
    """The manifolds of the rows: each bouncy manifold bouncing now (``due``) with the bouncy
    manifolds touching it through dynamic bodies (``_touching``), found breadth first; a row
    is kept when it has two manifolds or more and at most MAX_ROW (a larger cluster is a pile,
    not a row: it keeps the solve's answer, and the search stops there).  Returns the mask and
    the rows' manifolds in the order found: outward from the struck contact, the order in which
    an impact travels, so that one sweep of the impact pass usually carries it to the end."""
    rows = np.zeros(nc, dtype=np.bool_)
    struck = False
    for d in range(nc):
        struck = struck or (due[d] and C.e[d] >= ROW_RESTITUTION)
    if not struck:
        return rows, np.empty(0, dtype=np.int64)
    first, nxt = _adjacency(SB, C, nc, n)
    seen = np.zeros(nc, dtype=np.bool_)
    queue = np.empty(nc, dtype=np.int64)
    order = np.empty(nc, dtype=np.int64)
    m = 0
    for d in range(nc):
        if not due[d] or seen[d] or C.e[d] < ROW_RESTITUTION:
            continue
        seen[d] = True
        queue[0] = d
        head = 0
        tail = 1
        while head < tail and tail <= MAX_ROW:
            k = queue[head]
            head += 1
            for i in (C.a[k], C.b[k]):
                if not _dynamic(SB, i):
                    continue
                x = first[i]
                while x >= 0:
                    j = x // 2
                    x = nxt[x]
                    if not seen[j] and (due[j] or _touching(SB, C, R, j, slop)):
                        seen[j] = True
                        queue[tail] = j
                        tail += 1
        if head == tail and 2 <= tail <= MAX_ROW:
            for x in range(tail):
                rows[queue[x]] = True
                order[m] = queue[x]
                m += 1
    return rows, order[:m]


@kernel(runtime=True)
def chain_impacts(c, p, SB, C, R, due):
    """Resolve the rows of touching bodies struck in this sub-step pair by pair (module doc);
    returns which manifolds it resolved (the bounce of contact_restitution.py skips them)."""
    rows, order = _rows(SB, C, R, c.nc, c.n, due, c.slop)
    m = len(order)
    if m == 0:
        return rows
    for k in order:  # the solve's normal impulses of this sub-step, taken back
        for q in range(C.count[k]):
            o = q * PT
            _push(SB, C.a[k], C.b[k], R[k, NX], R[k, NY], R[k, o + RNA], R[k, o + RNB], -R[k, o + JN])
            R[k, o + JN] = 0.0
            R[k, o + BOUNCED] = 1.0
    threshold = p.restitution_threshold
    for _ in range(m):
        struck = False
        for k in order:
            a = C.a[k]
            b = C.b[k]
            nx = R[k, NX]
            ny = R[k, NY]
            for q in range(C.count[k]):
                o = q * PT
                rna = R[k, o + RNA]
                rnb = R[k, o + RNB]
                vn = ((SB[b, VX] - SB[a, VX]) * nx + (SB[b, VY] - SB[a, VY]) * ny
                      + SB[b, W] * rnb - SB[a, W] * rna)
                if vn >= 0.0:
                    continue
                e = C.e[k] if -vn > threshold else 0.0
                _push(SB, a, b, nx, ny, rna, rnb, -(1.0 + e) * R[k, o + MASS_N] * vn)
                struck = struck or e > 0.0
        if not struck:
            break
    return rows
