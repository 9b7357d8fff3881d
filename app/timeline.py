"""The timeline (issue 15): while the simulation plays, a snapshot of the world every
``interval`` seconds of simulated time, the last ``span`` seconds of them in a bounded ring.
Scrubbing restores the snapshot at or before the chosen time (``world.restore``: bit-identical
continuation); stepping on from a scrubbed moment discards the snapshots after it.  The core
restores only into a world with the same bodies, fixtures, springs and joints, so an edit that
changes the topology (add, delete) clears the timeline; so does a reset or another document.  A
drag holds the mouse joint only while the button is down: no snapshot is taken then, and the
snapshots before and after it stay (a throw can be rewound).  Cost for a 1000-body scene: docs/sandbox.md, "Timeline"."""
from __future__ import annotations

from collections import deque

from physics.snapshot import check

INTERVAL = 0.25     # s of simulated time between snapshots
SPAN = 60.0         # s of simulated time kept
BUDGET = 512 * 2**20    # bytes the ring may hold: a 1000-body ring of 60 s takes 255 MiB, 5000 bodies get ~24 s


def nbytes(x) -> int:
    """The array bytes in a snapshot (its tables, vertices, contacts: nearly all of it)."""
    if hasattr(x, "nbytes"):
        return int(x.nbytes)
    if isinstance(x, dict):
        return sum(nbytes(v) for v in x.values())
    if isinstance(x, (list, tuple)):
        return sum(nbytes(v) for v in x)
    if hasattr(x, "__slots__"):
        return sum(nbytes(getattr(x, k, None)) for k in x.__slots__)
    return 0


class Timeline:
    """Snapshots ``(time, snapshot)`` oldest first; ``cursor`` is the index restored by the last
    scrub (None: the world is at or after the newest snapshot).  At most ``span / interval + 1``
    of them, fewer if that many would hold more than ``budget`` bytes (``capacity``)."""

    def __init__(self, interval=INTERVAL, span=SPAN, budget=BUDGET):
        self.interval = float(interval)
        self.span = float(span)
        self.budget = budget
        self.entries: deque = deque(maxlen=int(round(span / interval)) + 1)
        self.capacity = self.entries.maxlen
        self.cursor = None
        self.cleared = 0              # how many times an edit or reset cleared it (the status file shows it)
        self.held = False             # the topology differs only by a tool's joint (a click's mouse drag)
        self.mark_of = None           # () -> what to remember with each snapshot (app.scrub_marks)
        self.marks: dict = {}         # id(snapshot) -> its mark
        self._signature = None

    def __len__(self):
        return len(self.entries)

    def times(self):
        return [t for t, _ in self.entries]

    def range(self):
        """(oldest, newest) snapshot time, or None when empty."""
        return (self.entries[0][0], self.entries[-1][0]) if self.entries else None

    def record(self, world):
        """Called while playing, before a frame's steps and after each step (so snapshots fall on
        exact multiples of the interval's steps).  If the world steps on from a scrubbed moment,
        the snapshots after it go first; then a snapshot if ``interval`` has passed since the
        newest one (half a step early, so float sums of dt do not skip one)."""
        self.drop_future()
        if self.held:     # the mouse drag's joint is no edit: the drag is a gap between snapshots
            return
        t = world.time
        if not self.entries or t >= self.entries[-1][0] + self.interval - 0.5 * world.dt:
            snap = world.snapshot()
            if not self.entries:      # the scene's size sets how many fit the budget
                self.capacity = max(2, min(self.entries.maxlen, self.budget // max(1, nbytes(snap))))
            self.entries.append((t, snap))
            if self.mark_of is not None:
                self.marks[id(snap)] = self.mark_of()
            while len(self.entries) > self.capacity:
                self.marks.pop(id(self.entries.popleft()[1]), None)

    def drop_future(self):
        """The world steps on from a scrubbed moment (played or single-stepped): the snapshots
        after it showed a future that no longer happens."""
        if self.cursor is not None:
            while len(self.entries) > self.cursor + 1:
                self.marks.pop(id(self.entries.pop()[1]), None)
            self.cursor = None

    def watch(self, world, signature, transient=False):
        """Clear the timeline if the world's topology changed.  ``signature`` is anything that
        changes with every edit (history version, counts of bodies and joints): only then are the
        world's ids compared with the newest snapshot's.  ``transient``: a tool's joint exists
        (a drag holds a mouse joint until release), which is no edit: the timeline is only held
        (no scrubbing, no snapshots) until the joint goes, and the drag or throw stays on it as
        the steps between two snapshots.  Returns True if it cleared."""
        if signature == self._signature:
            return False
        self._signature = signature
        self.held = False
        if not self.entries:
            return False
        try:
            check(world, self.entries[-1][1])
        except ValueError:
            if transient:
                self.held = True
                return False
            self.clear()
            return True
        return False

    def scrub(self, world, t):
        """Restore the newest snapshot taken at or before time ``t`` (the oldest if ``t`` is before
        it); returns its time, or None if there is none or the core refused (then cleared)."""
        if not self.entries or self.held:
            return None
        k = 0
        for i, (ti, _) in enumerate(self.entries):
            if ti <= t + 1e-9:
                k = i
        try:
            world.restore(self.entries[k][1])
        except ValueError:
            self.clear()
            return None
        self.cursor = k
        return self.entries[k][0]

    def mark_at_cursor(self):
        """The mark of the snapshot the last scrub restored, or None."""
        return None if self.cursor is None else self.marks.get(id(self.entries[self.cursor][1]))

    def clear(self):
        """Drop every snapshot (a topology edit, a reset, another document)."""
        if self.entries:
            self.cleared += 1
        self.entries.clear()
        self.marks.clear()
        self.cursor = None
        self.held = False

    def describe(self) -> dict:
        """For the status file: how many snapshots, their time range, the scrub cursor."""
        rng = self.range()
        return {"n": len(self.entries), "range": list(rng) if rng else None, "cursor": self.cursor,
                "cleared": self.cleared, "held": self.held, "capacity": self.capacity, "interval": self.interval, "span": self.span}
