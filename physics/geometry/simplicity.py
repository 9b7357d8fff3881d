"""Is a closed polygon simple?  ``first_meeting(points)``: two non-neighbouring edges that meet, or None.

A plane sweep (Shamos and Hoey, "Geometric intersection problems", FOCS 1976): events are
the vertices in lexicographic (x, then y) order, which is a sweep line turned by an
infinitesimal angle, so vertical edges need no special case.  The sweep keeps the edges it
crosses sorted from bottom to top; two edges that meet are neighbours in that order at some
event before the leftmost meeting point, so testing each pair that becomes neighbours finds
a meeting if there is one.  O(n log n) orientation tests for n vertices (the list inserts are
memmoves: linear, but with a tiny constant next to the Python-level tests).

Orientation signs are exact (``orient``): Shewchuk's error bound decides the sign from the
floating-point determinant when it can ("Adaptive precision floating-point arithmetic and
fast robust geometric predicates", 1997, ccwerrboundA), and exact rational arithmetic
decides the rest, so the sorted order never contradicts itself.

Neighbouring edges (i, i + 1) share a vertex and are not tested against each other: the
caller has removed straight and reversing vertices, so they meet only there.
"""
from __future__ import annotations

from fractions import Fraction

# Shewchuk's ccwerrboundA = (3 + 16 eps) eps with eps = 2^-53
_ERRBOUND = (3.0 + 16.0 * 2.0 ** -53) * 2.0 ** -53


def orient(a, b, c) -> int:
    """Sign of the cross product (b - a) x (c - a): 1 if c is left of a -> b, -1 right, 0 on the line."""
    if c == a or c == b:  # an edge's own end: the sweep asks this at every vertex
        return 0
    left = (a[0] - c[0]) * (b[1] - c[1])
    right = (a[1] - c[1]) * (b[0] - c[0])
    det = left - right
    if abs(det) > _ERRBOUND * (abs(left) + abs(right)):
        return 1 if det > 0 else -1
    ax, ay, bx, by, cx, cy = map(Fraction, (*a, *b, *c))
    exact = (ax - cx) * (by - cy) - (ay - cy) * (bx - cx)
    return (exact > 0) - (exact < 0)


def _meet(a, b, c, d) -> bool:
    """Whether the closed segments a-b and c-d share a point."""
    o1, o2 = orient(a, b, c), orient(a, b, d)
    o3, o4 = orient(c, d, a), orient(c, d, b)
    if o1 == o2 == o3 == o4 == 0:  # on one line: do their lexicographic spans overlap?
        return max(min(a, b), min(c, d)) <= min(max(a, b), max(c, d))
    return o1 * o2 <= 0 and o3 * o4 <= 0


def first_meeting(points) -> tuple[int, int] | None:
    """(i, j), i < j: edges i (points[i] -> points[i + 1]) and j that meet although they are not
    neighbours, or None if the closed polygon is simple.  ``points``: (x, y) float pairs with no
    two consecutive ones equal and no straight or reversing vertex."""
    p = [(float(x), float(y)) for x, y in points]
    n = len(p)
    order = sorted(range(n), key=p.__getitem__)
    for a, b in zip(order, order[1:]):  # one point visited twice: the edges leaving it meet there
        if p[a] == p[b]:
            return min(a, b), max(a, b)
    rank = [0] * n
    for r, i in enumerate(order):
        rank[i] = r
    left = [i if rank[i] < rank[(i + 1) % n] else (i + 1) % n for i in range(n)]  # edge i's left end
    sweep = _Sweep(p, left)
    for v in order:
        found = sweep.event(v)
        if found:
            return found
    return None


class _Sweep:
    """The edges the sweep line crosses, bottom to top (edge i runs from p[i] to p[i + 1])."""

    def __init__(self, p, left):
        self.p, self.left, self.n = p, left, len(p)
        self.status: list[int] = []

    def ends(self, e):
        """(left end, right end) of edge e as points."""
        a, b = self.p[e], self.p[(e + 1) % self.n]
        return (a, b) if self.left[e] == e else (b, a)

    def _below(self, e, v) -> bool:
        lo, hi = self.ends(e)
        return orient(lo, hi, self.p[v]) > 0

    def event(self, v):
        """Process vertex v: remove the edges ending there, insert those starting there."""
        n, p = self.n, self.p
        incident = ((v - 1) % n, v)
        status = self.status
        lo, hi = 0, len(status)
        while lo < hi:  # the first edge not strictly below p[v]
            mid = (lo + hi) // 2
            if self._below(status[mid], v):
                lo = mid + 1
            else:
                hi = mid
        k = lo
        while k < len(status) and orient(*self.ends(status[k]), p[v]) == 0:
            if status[k] not in incident:  # p[v] lies on an edge that does not end there
                return self._pair(status[k], v)
            k += 1
        ending = [e for e in incident if self.left[e] != v]
        if sorted(status[lo:k]) != sorted(ending):  # cannot happen with exact signs; refuse, never guess
            return self._pair(*incident)
        del status[lo:k]
        starting = [e for e in incident if self.left[e] == v]
        if len(starting) == 2:  # bottom to top: the second lies left of the first, seen from v
            a, b = starting
            if orient(p[v], self.ends(a)[1], self.ends(b)[1]) < 0:
                starting = [b, a]
        status[lo:lo] = starting
        pairs = [(lo - 1, lo), (lo + len(starting) - 1, lo + len(starting))]
        if not starting:
            pairs = [(lo - 1, lo)]
        for i, j in pairs:
            if 0 <= i and j < len(status) and self._touch(status[i], status[j]):
                return self._pair(status[i], status[j])
        return None

    def _touch(self, e, f) -> bool:
        if (e - f) % self.n in (1, self.n - 1):
            return False
        return _meet(*self.ends(e), *self.ends(f))

    @staticmethod
    def _pair(e, f):
        return (e, f) if e < f else (f, e)

