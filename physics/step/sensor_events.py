"""Which sensors overlap which fixtures, step to step: the arrays behind ``world.sensor_events()``.

The pipeline splits the sensor pairs off the contact pairs (collision/broadphase/sensor_split.py)
and tests their exact shapes (collision/narrowphase/sensor_overlap.py) at the step's geometry
(start-of-step positions, the contacts' own).  Keys are (sensor id << 32) | visitor id; this
step's set is compared with the last one (begins, ends), a pair gone only to sleep is kept
(resting.py).  A world that never had a sensor runs none of it.
"""
from __future__ import annotations

import numpy as np

from ..collision.narrowphase.sensor_overlap import sensor_overlaps
from .resting import kept

_NONE = np.zeros(0, np.int64)


class SensorTracker:
    """The overlapping (sensor, visitor) keys (sorted) and the last step's begins and ends."""

    def __init__(self):
        self.keys = _NONE
        self.begin = _NONE
        self.ends = _NONE
        self.pairs = np.zeros((64, 2), np.int32)
        self._out = np.zeros(64, np.int64)
        self._found = None

    def room(self, npairs: int) -> np.ndarray:
        """The sensor-pair buffer, with room for ``npairs`` rows."""
        if npairs > len(self.pairs):
            self.pairs = np.zeros((2 * npairs, 2), np.int32)
            self._out = np.zeros(2 * npairs, np.int64)
        return self.pairs

    @property
    def keys(self) -> np.ndarray:
        """The overlapping keys, sorted.  Setting them sets ``active``: whether overlaps are open
        (they must end even once the last sensor is gone), a plain attribute because the step
        asks it every time."""
        return self._keys

    @keys.setter
    def keys(self, keys) -> None:
        self._keys = keys
        self.active = len(keys) > 0

    def sense(self, ctx, store, ns: int) -> None:
        """The overlapping keys of the first ``ns`` sensor pairs (committed at the step's end)."""
        k = sensor_overlaps(ctx.array, store.bodies.view, store.fixtures.view, store.verts.view, self.pairs, ns,
                            self._out) if ns else 0
        self._found = np.sort(self._out[:k])

    def commit(self, world) -> None:
        """Begins and ends of this step (no sense() this step: nothing overlaps)."""
        found = _NONE if self._found is None else self._found
        self._found = None
        self.begin = found[~np.isin(found, self.keys)]
        gone = self.keys[~np.isin(self.keys, found)]
        keep = kept(world, gone)
        self.keys = np.union1d(found, gone[keep]) if keep.any() else found
        self.ends = gone[~keep]

    def put(self, keys) -> None:
        """Restore the overlapping keys (the events of the last step are gone)."""
        self.keys = np.array(keys, np.int64)
        self.begin = self.ends = _NONE
        self._found = None
