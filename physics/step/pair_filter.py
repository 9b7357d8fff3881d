"""``world.pair_filter``: a user function asked once about each new fixture pair.

Box2D's custom filter: ``fn(fixture_a, fixture_b) -> bool`` (a: the lower fixture id; for a
sensor pair, the sensor first) is called when the broad phase first reports a pair (their
boxes came to overlap), after the category/mask/group filter and the joints; the verdict
holds until the boxes part (or a fixture goes), so a pair that meets again is asked again.
False drops the pair before the narrow phase: no contact, no events, no sensor overlap.
Runs only when a filter is set (a Python call per new pair; the kept verdicts a dict).
"""
from __future__ import annotations

import numpy as np

from ..store.contacts import PAIR_LOW as LOW


class PairFilter:
    """The verdicts of the world's pair filter, by fixture-pair key (lower id << 32 | higher id)."""

    def __init__(self):
        self.verdicts: dict[int, bool] = {}
        self._seen: set = set()

    def clear(self) -> None:
        """Forget every verdict (a new filter asks again)."""
        self.verdicts = {}

    def apply(self, world, pairs: np.ndarray, npairs: int, sensors: bool = False) -> int:
        """Compact the fixture-slot pairs ``pairs[:npairs]`` to those the filter lets through
        (``sensors``: the pairs are (sensor, visitor), asked in that order)."""
        if npairs == 0:
            return 0
        fid = world._store.fixtures.view.id
        ia, ib = fid[pairs[:npairs, 0]], fid[pairs[:npairs, 1]]
        lo, hi = np.minimum(ia, ib), np.maximum(ia, ib)
        first, second = (ia, ib) if sensors else (lo, hi)
        handles = world._fixture_handles
        ok = np.empty(npairs, bool)
        for k, key in enumerate(((lo << 32) | hi).tolist()):
            self._seen.add(key)
            v = self.verdicts.get(key)
            if v is None:
                v = self.verdicts[key] = _ask(world, handles[int(first[k])], handles[int(second[k])])
            ok[k] = v
        if not ok.all():
            keep = np.nonzero(ok)[0]
            pairs[:len(keep)] = pairs[keep]
        return int(ok.sum())

    def forget_parted(self, world) -> None:
        """Drop the verdicts of pairs the broad phase did not report this step whose fixtures are
        gone or whose boxes no longer overlap (a sleeping pair keeps its verdict)."""
        store = world._store.fixtures
        box = store.view.aabb
        for key in [k for k in self.verdicts if k not in self._seen]:
            i, j = store.slot_of.get(key >> 32), store.slot_of.get(key & LOW)
            if i is None or j is None or not _overlap(box[i], box[j]):
                del self.verdicts[key]
        self._seen = set()


def _ask(world, a, b) -> bool:
    """The filter's verdict on fixtures a and b.  The world refuses edits while it runs
    (world._check_editable), and anything it raises becomes a refused step: SimulationError, so
    step() reverts the world and sets world.fault instead of leaving it half-stepped."""
    from ..errors import SimulationError
    world._in_callback += 1
    try:
        return bool(world._pair_filter(a, b))
    except Exception as exc:  # noqa: BLE001  (user code: any exception refuses the step)
        raise SimulationError(f"pair_filter raised {type(exc).__name__}: {exc}; the world was reverted to the "
                              "state before the step", stage="collide") from exc
    finally:
        world._in_callback -= 1


def _overlap(a, b) -> bool:
    return bool(a[0] <= b[2] and b[0] <= a[2] and a[1] <= b[3] and b[1] <= a[3])
