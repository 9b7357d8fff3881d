"""Contact hits for the stats window's readout: how often the selected body is hit.

The core reports each step's hits (``world.contact_events().hit``: touching contacts whose
approach speed exceeded ``world.hit_event_threshold``, 1 m/s by default).  The step loop calls
:meth:`HitRate.on_step` after every step while a body is watched, so no hit within a frame's
steps is missed; nothing is asked of the core while no body is selected."""
from __future__ import annotations

from collections import deque


def pair_key(contact) -> tuple:
    """A contact's fixture pair (ids, smaller first)."""
    a, b = contact.fixture_a, contact.fixture_b
    ia, ib = (a.id if a is not None else -1), (b.id if b is not None else -1)
    return (ia, ib) if ia <= ib else (ib, ia)


class HitRate:
    """Contact hits of one body: their world times, and how many fell in the last ``window``
    seconds of simulated time (hits per second)."""

    def __init__(self, window: float = 1.0):
        self.window = window
        self.body = None
        self.times: deque = deque(maxlen=10_000)
        self._time = None

    def update(self, world, body_id, contacts=None):
        """Watch ``body_id`` (another body, or time going back -- a reset, a timeline scrub --
        starts the count again); ``contacts`` is unused (the hits come from on_step)."""
        t = world.time
        if body_id != self.body or (self._time is not None and t < self._time):
            self.body, self._time = body_id, t
            self.times.clear()
        self._time = t

    def on_step(self, world):
        """After a step: record the watched body's hits of that step at the world's time."""
        if self.body is None:
            return
        hits = world.contact_events().hit
        if hits:
            t = world.time
            self.times.extend(t for h in hits if self.body in (h.fixture_a.body.id, h.fixture_b.body.id))
        self._time = world.time

    def per_second(self) -> float:
        if self._time is None:
            return 0.0
        return sum(1 for x in self.times if x > self._time - self.window) / self.window
