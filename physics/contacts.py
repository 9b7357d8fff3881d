"""Contact manifolds as arrays: the narrow phase writes them, solvers read them.

One row per touching (or speculatively close) pair, at most two points per
row.  The normal points from body ``a`` to body ``b``.  ``depth`` is the
penetration (positive when overlapping, negative for a speculative point
that is still apart by that distance).  ``feature`` identifies the pair of
features (vertex/edge indices) that made a point so that accumulated
impulses ``jn``/``jt`` carry over between steps (warm starting).  Rows are
sorted by ``key`` (stable ids of a and b) so matching with the previous
step is a merge.  The remaining fields are scratch space that every solver
mode shares (anchors, effective masses, restitution reference speeds).
"""
from __future__ import annotations

from collections import namedtuple

import numpy as np

from .store import allocate, f8, i1, i4, i8

MAX_POINTS = 2

CONTACT_FIELDS = {
    "a": ((), i4),                 # body slot of a (the normal's tail)
    "b": ((), i4),                 # body slot of b
    "key": ((), i8),               # (id_a << 32) | id_b, sorted ascending
    "count": ((), i1),             # points in this manifold (1 or 2)
    "normal": ((2,), f8),          # unit normal, world, from a to b
    "point": ((MAX_POINTS, 2), f8),  # world contact points (midway between the surfaces)
    "depth": ((MAX_POINTS,), f8),  # penetration > 0, speculative gap < 0
    "feature": ((MAX_POINTS,), i4),  # feature ids for warm-start matching
    "jn": ((MAX_POINTS,), f8),     # accumulated normal impulse (N s)
    "jt": ((MAX_POINTS,), f8),     # accumulated tangent impulse (N s)
    "e": ((), f8),                 # combined restitution: max(e_a, e_b)
    "mu_s": ((), f8),              # combined static friction: sqrt(mu_a mu_b)
    "mu_d": ((), f8),              # combined dynamic friction: sqrt(mu_a mu_b)
    # scratch shared by the solver modes
    "ra": ((MAX_POINTS, 2), f8),   # anchor relative to a's centre of mass, world frame
    "rb": ((MAX_POINTS, 2), f8),   # anchor relative to b's centre of mass
    "mass_n": ((MAX_POINTS,), f8),  # effective mass along the normal
    "mass_t": ((MAX_POINTS,), f8),  # effective mass along the tangent
    "vn0": ((MAX_POINTS,), f8),    # relative normal velocity before solving (restitution)
    "mu": ((MAX_POINTS,), f8),     # friction coefficient in force this step (static or dynamic)
    "bias": ((MAX_POINTS,), f8),   # per-point velocity bias / scratch
}

Contacts = namedtuple("Contacts", list(CONTACT_FIELDS))


class ContactBuffer:
    """Two contact tables (this step's and the previous), swapped every step."""

    def __init__(self, cap: int = 256):
        self.cur = Contacts(**allocate(CONTACT_FIELDS, cap))
        self.prev = Contacts(**allocate(CONTACT_FIELDS, cap))
        self.n = 0
        self.n_prev = 0

    @property
    def capacity(self) -> int:
        return len(self.cur.a)

    def ensure(self, need: int) -> None:
        if need > self.capacity:
            cap = max(need, 2 * self.capacity)
            self.cur = Contacts(**allocate(CONTACT_FIELDS, cap))
            old = self.prev
            self.prev = Contacts(**allocate(CONTACT_FIELDS, cap))
            for k in CONTACT_FIELDS:
                getattr(self.prev, k)[: self.n_prev] = getattr(old, k)[: self.n_prev]

    def swap(self) -> None:
        """Make the current table the previous one before a new narrow phase."""
        self.cur, self.prev = self.prev, self.cur
        self.n_prev, self.n = self.n, 0

    def remap_removed_body(self, removed: int, moved_from: int) -> None:
        """Drop rows touching a removed body slot; renumber the swapped-in body."""
        for tab, attr in ((self.cur, "n"), (self.prev, "n_prev")):
            n = getattr(self, attr)
            a, b = tab.a[:n], tab.b[:n]
            keep = (a != removed) & (b != removed)
            a[a == moved_from] = removed
            b[b == moved_from] = removed
            if not keep.all():
                idx = np.nonzero(keep)[0]
                for k in CONTACT_FIELDS:
                    arr = getattr(tab, k)
                    arr[: len(idx)] = arr[idx]
                setattr(self, attr, len(idx))
