"""Contact manifolds as arrays: the narrow phase writes them, solvers read them.

One row per touching (or speculatively close) pair, at most two points per
row.  The normal points from body ``a`` to body ``b``.  ``depth`` is the
penetration (positive when overlapping, negative for a speculative point
that is still apart by that distance).  ``feature`` identifies the pair of
features (vertex/edge indices) that made a point so that the per-point state
carries over between steps (warm starting).  Rows are sorted by ``key``
(stable ids of a and b) so matching with the previous step is a merge.

Every field means one thing in every solver mode.  What persists per point
from step to step:

* ``jn``, ``jt``: the accumulated normal and tangent impulses (N s) over the
  time span ``ContactBuffer.span`` of the mode that wrote them (a whole step
  for sequential impulses, one sub-step for soft_step);
* ``stick``: the stretch (m) of a penalty contact's tangential stick spring;
* ``approach``: the fastest approach speed a penalty contact has seen, as the
  most negative normal speed (m/s, <= 0).

and per row, ``colour``: the graph colour the coloured contact solve gave the pair
(constraints/colouring.py), kept while the pair has a row so that one contact coming or
going does not reorder the others' solve (Box2D v3's constraint graph); a new pair has -1.

Per-step scratch of a solver (anchors, effective masses, biases) lives in that
solver's own arrays, never here.
"""
from __future__ import annotations

import numpy as np

from .table import allocate, f8, i1, i4, i8
from .table_view import view_class

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
    "jn": ((MAX_POINTS,), f8),     # accumulated normal impulse (N s) over `span`
    "jt": ((MAX_POINTS,), f8),     # accumulated tangent impulse (N s) over `span`
    "stick": ((MAX_POINTS,), f8),  # penalty stick-spring stretch (m)
    "approach": ((MAX_POINTS,), f8),  # fastest approach seen by a penalty contact (m/s, <= 0)
    "e": ((), f8),                 # combined restitution: max(e_a, e_b)
    "mu_s": ((), f8),              # combined static friction: sqrt(mu_a mu_b)
    "mu_d": ((), f8),              # combined dynamic friction: sqrt(mu_a mu_b)
    "colour": ((), i1),            # soft_step "coloured" layout's graph colour, kept while touching; -1: none yet
}
#: largest growth of the impulses' time span that ContactBuffer.adopt rescales (beyond: cold start);
#: 4 covers soft_step -> sequential_impulse at the default 4 sub-steps
MAX_SPAN_GROWTH = 4.0
#: the low half of a fixture-pair key ((id_a << 32) | id_b): ``key & PAIR_LOW`` is id_b
PAIR_LOW = 0xFFFFFFFF
#: the per-point state the narrow phase carries from a step's rows to the next step's
CARRIED = ("jn", "jt", "stick", "approach")

Contacts = view_class("Contacts", CONTACT_FIELDS, "contacts")


class ContactBuffer:
    """Two contact tables (this step's and the previous), swapped every step.

    ``span`` is the time span (s) the accumulated impulses ``jn``/``jt`` of the
    current table stand for, and ``span_step`` the step whose solve may use them
    as they are (see :meth:`adopt`).  ``full``: this world has met a pair the narrow phase's
    lean kernel does not handle (collision/narrowphase/kernel.py), so it uses the whole one.
    """

    def __init__(self, cap: int = 256):
        self._tables(cap)
        self.n = 0
        self.n_prev = 0
        self.span = 0.0
        self.span_step = -1
        self.full = False

    @property
    def capacity(self) -> int:
        return len(self.cur.a)

    def ensure(self, need: int, limit: int | None = None) -> None:
        """Room for ``need`` rows: twice the capacity or twice ``need``, whichever is more (a pile
        woken row by row asks for half as many again each step), but never beyond ``limit`` rows
        (collision/narrowphase/limit.py) unless ``need`` itself is larger."""
        if need > self.capacity:
            grown = 2 * max(need, self.capacity)
            cap = max(need, grown if limit is None else min(grown, limit))
            old = self.prev_cols
            self._tables(cap)
            for a, b in zip(self.prev_cols.flat, old.flat):
                a[: self.n_prev] = b[: self.n_prev]

    def _tables(self, cap: int) -> None:
        """Two zeroed tables of ``cap`` rows: their columns (``*_cols``, whose ``flat`` arrays the
        step's compiled entry points take) and their views (``cur``, ``prev``)."""
        self.cur_cols = allocate(CONTACT_FIELDS, cap)
        self.prev_cols = allocate(CONTACT_FIELDS, cap)
        self.cur = Contacts(**self.cur_cols)
        self.prev = Contacts(**self.prev_cols)

    def swap(self, n: int = 0) -> None:
        """Make the current table the previous one before a new narrow phase (or, with ``n``,
        after the step driver's: the new current table holds ``n`` rows)."""
        self.cur, self.prev = self.prev, self.cur
        self.cur_cols, self.prev_cols = self.prev_cols, self.cur_cols
        self.n_prev, self.n = self.n, n

    def adopt(self, span: float, step: int) -> None:
        """Make the current impulses mean impulse over ``span`` seconds for the solve of ``step``.

        What the accumulated impulses mean depends on the mode that wrote them:
        ``sequential_impulse`` stores the impulse of a whole step, ``soft_step`` that of
        one sub-step, the seed modes none.  Re-applying another mode's impulses as if
        they were one's own kicks a resting pile (4x too much load after
        sequential_impulse -> soft_step), so impulses written for the previous step
        by a mode that recorded its span are rescaled to the caller's span; impulses
        of unknown origin (a mode that does not record itself, or an older step) are
        dropped, which costs only one cold step (Catto 2005: warm starting is only an
        initial guess).

        Rescaling is right for the part of an impulse that a force makes over the span
        (a resting load: j = F h), not for the part that changes a velocity at once (an
        impact, a push-out: j = m dv, whatever h is).  After a large growth of the span
        (a step rate cut from 1 MHz to 60 Hz) the second part, scaled up, would launch
        bodies (a pile stirred at 1 MHz threw boxes at 140 m/s once back at 60 Hz), so
        a span growing more than MAX_SPAN_GROWTH times drops the impulses instead.
        """
        r = self.adopt_factor(span, step)
        n = self.n
        if r != 1.0 and n:
            self.cur.jn[:n] *= r
            self.cur.jt[:n] *= r

    def adopt_factor(self, span: float, step: int) -> float:
        """What :meth:`adopt` multiplies the current impulses by (1 keeps them, 0 drops them),
        with the span recorded as adopt does; the step driver applies the factor itself."""
        r = 1.0
        if self.span_step == step:
            if self.span != span:
                r = span / self.span
                if r > MAX_SPAN_GROWTH:
                    r = 0.0
        else:
            r = 0.0
        # the next step sees these impulses (span) if nobody else steps in between
        self.span = span
        self.span_step = step + 1
        return r

    def reserve(self, need: int, limit: int | None = None) -> None:
        """Room for ``need`` rows before a step's swap (the current rows are kept)."""
        if need > self.capacity:
            n = self.n
            self.swap()
            self.ensure(need, limit)
            self.swap()
            self.n = n

    def forget_impulses(self) -> None:
        """Zero every carried point state of both tables (after a refused step)."""
        for tab in (self.cur, self.prev):
            for k in CARRIED:
                getattr(tab, k)[:] = 0.0

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
