"""Pairing of begin/end events across a run: every begin has exactly one end, or the pair is
still open (touching, or overlapping a sensor) at the end of the run."""
from __future__ import annotations


class Pairing:
    """Feed it each step's (begin pairs, end pairs); it fails at the first unpaired event."""

    def __init__(self):
        self.open: set = set()
        self.begins = 0
        self.ends = 0

    def feed(self, begins, ends) -> None:
        for a, b in ends:
            key = (a.id, b.id)
            assert key in self.open, f"end without a begin: {key}"
            self.open.remove(key)
            self.ends += 1
        for a, b in begins:
            key = (a.id, b.id)
            assert key not in self.open, f"a second begin without an end: {key}"
            self.open.add(key)
            self.begins += 1

    def contacts(self, world) -> None:
        ev = world.contact_events()
        self.feed([(e.fixture_a, e.fixture_b) for e in ev.begin], ev.end)

    def sensors(self, world) -> None:
        ev = world.sensor_events()
        self.feed(ev.begin, ev.end)


def touching(world) -> set:
    """The (fixture_a id, fixture_b id) pairs of world.contacts() (the lower id first)."""
    return {tuple(sorted((c.fixture_a.id, c.fixture_b.id))) for c in world.contacts()}
