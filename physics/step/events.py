"""The step's events stage: sensor pairs, the pair filter, and the touching and overlap sets.

The pipeline hands this stage the broad phase's pairs (:meth:`StepEvents.pairs`: the fixture
filter, sensor pairs split off when the world has sensors, the user's pair filter when one
is set) and calls :meth:`StepEvents.commit` once the step is accepted (a refused step leaves
the sets as they were).  What a world pays per step: nothing for sensors it has not got or a
filter it has not set; one merge over its contact rows inside the step's closing kernel
(contact_events.py).  The
events of a step replace the previous step's (Box2D); a step skipped because every body
sleeps has none.  physics/events.py makes the Python objects on demand.
"""
from __future__ import annotations

import numpy as np

from ..collision.broadphase.fixture_filter import filter_pairs_flat
from ..collision.broadphase.sensor_split import split_sensor_pairs
from .contact_events import ContactTracker
from .pair_filter import LOW, PairFilter
from .sensor_events import SensorTracker

_NONE = np.zeros(0, np.int64)


class StepEvents:
    """Trackers of one world; ``step`` is the world's step count after the step they describe."""

    def __init__(self):
        self.contacts = ContactTracker()
        self.sensors = SensorTracker()
        self.filter = PairFilter()
        self.step = -1
        self.cache: dict = {}  # Python events of ``step``, made when asked
        self._sensed = False

    def pairs(self, world, fixtures, pairs, npairs: int, keys) -> int:
        """Filter the broad phase's pairs in place; returns the contact pairs' count (the
        sensor pairs, if any, are in ``self.sensors.pairs``).  ``fixtures``: the fixture table."""
        self._sensed = world._n_sensors > 0 or self.sensors.active
        ns = 0
        if self._sensed:
            npairs, ns = split_sensor_pairs(fixtures.view, pairs, npairs, keys, self.sensors.room(npairs))
        else:
            npairs = filter_pairs_flat(*fixtures.arrays.flat, pairs, npairs, keys)
        npairs = int(npairs)
        if world._pair_filter is not None:
            npairs = self.filter.apply(world, pairs, npairs)
            ns = self.filter.apply(world, self.sensors.pairs, int(ns), sensors=True)
            self.filter.forget_parted(world)
        self._ns = int(ns)
        return npairs

    def sense(self, ctx, store) -> None:
        """Exact overlap of this step's sensor pairs (after the broad phase, at its geometry)."""
        if self._sensed:
            self.sensors.sense(ctx, store, self._ns)

    def commit(self, world, nt: int, nb: int, na: int) -> None:
        """The accepted step's touching and overlap sets, begins and ends (after the step count;
        ``nt, nb, na``: the counts of the touching merge end_step ran, contact_events.py)."""
        self.contacts.take(world, nt, nb, na)
        self._commit_sensors(world)

    def idle(self, world) -> None:
        """A step of a world without bodies: whatever touched or overlapped has ended."""
        if self.contacts.n or self.sensors.active:
            self.contacts.idle()
            self._sensed = True
            self.sensors._found = None
            self._commit_sensors(world)

    def _commit_sensors(self, world) -> None:
        if self._sensed:
            self.sensors.commit(world)
        else:
            self.sensors.begin = self.sensors.ends = _NONE
        self.step = world.steps
        if self.cache:  # (an empty one stands: a new dict per step costs more than the test)
            self.cache = {}
        if world._gone_fixtures:  # removed fixtures are named only by the ends of this step
            ends = np.concatenate([self.contacts.ends, self.sensors.ends])
            named = set((ends >> 32).tolist()) | set((ends & LOW).tolist())
            world._gone_fixtures = {k: v for k, v in world._gone_fixtures.items() if k in named}

    def clear(self) -> None:
        """Forget the last step's events (restore)."""
        self.step = -1
        self.cache = {}

    def state(self) -> tuple:
        """What a snapshot keeps: the touching keys, the overlap keys, the filter's verdicts."""
        return self.contacts.state(), self.sensors.keys.copy(), dict(self.filter.verdicts)

    def put(self, state) -> None:
        """Back to a snapshot's sets (its step's events are not kept: they are cleared)."""
        touching, overlaps, verdicts = state
        self.contacts.put(touching)
        self.sensors.put(overlaps)
        self.filter.verdicts = dict(verdicts)
        self.clear()
