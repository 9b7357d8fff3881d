"""Contact begins for the stats window's readout: which fixture pairs of a body started touching.

HOOK (issue 15): the core's contact events (branch events15) are not in main yet.  Until they
land, ``begun_pairs`` finds the begins in the app: the pairs touching in ``world.contacts()`` now
that did not touch at the previous call (one call a frame, so a touch that begins and ends
within one frame's steps -- at most 4 -- is missed, and one that lasts across frames counts
once).  When the core reports begin events, this one function changes to read them."""
from __future__ import annotations

from collections import deque


def pair_key(contact) -> tuple:
    """A contact's fixture pair (ids, smaller first)."""
    a, b = contact.fixture_a, contact.fixture_b
    ia, ib = (a.id if a is not None else -1), (b.id if b is not None else -1)
    return (ia, ib) if ia <= ib else (ib, ia)


def begun_pairs(world, contacts, before: set) -> tuple[set, set]:
    """(pairs touching now, pairs among them that began since ``before``) for ``contacts`` (the
    selected body's, from ``world.contacts()``)."""
    now = {pair_key(c) for c in contacts}
    return now, now - before


class HitRate:
    """Contact begins of one body: their world times, and how many fell in the last ``window``
    seconds of simulated time (hits per second)."""

    def __init__(self, window: float = 1.0):
        self.window = window
        self.body = None
        self.times: deque = deque(maxlen=10_000)
        self._pairs: set = set()
        self._time = None

    def update(self, world, body_id, contacts):
        """Count the begins of ``body_id``'s ``contacts`` if world time moved (another body, or
        time going back -- a reset, a timeline scrub -- starts the count again)."""
        t = world.time
        if body_id != self.body or (self._time is not None and t < self._time):
            self.body, self._pairs, self._time = body_id, set(), None
            self.times.clear()
        if t == self._time:
            return
        first = self._time is None
        self._time = t
        self._pairs, begun = begun_pairs(world, contacts, self._pairs)
        if not first:                      # touching when first looked at: not a hit we saw begin
            self.times.extend([t] * len(begun))

    def per_second(self) -> float:
        if self._time is None:
            return 0.0
        return sum(1 for x in self.times if x > self._time - self.window) / self.window
