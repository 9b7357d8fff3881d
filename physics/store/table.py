"""Growable structure-of-arrays tables with stable ids.

Every field is one numpy array of a shared capacity; live entries occupy the
dense range ``0..n-1`` so kernels loop over ``range(n)`` without holes.
Removal swaps the last entry into the hole, so an entry's *slot* can change; the
stable handle is its *id*, mapped to a slot by ``slot_of``.  Kernels receive
a table's arrays as one namedtuple (one argument, unboxed once per call).
"""
from __future__ import annotations

import numpy as np

f8, i1, i4, i8 = np.float64, np.int8, np.int32, np.int64


def allocate(fields: dict, cap: int) -> dict:
    """Zeroed arrays for ``fields`` (name: (per-entry shape, dtype)) with ``cap`` entries."""
    return {k: np.zeros((cap,) + shp, dtype=dt) for k, (shp, dt) in fields.items()}


def grown(arrays: dict, cap: int) -> dict:
    """Copies of ``arrays`` with a larger first dimension (contents kept)."""
    out = {}
    for k, a in arrays.items():
        b = np.zeros((cap,) + a.shape[1:], dtype=a.dtype)
        b[: len(a)] = a
        out[k] = b
    return out


class Table:
    """A growable dense table of SoA fields with stable ids (swap-remove)."""

    def __init__(self, fields: dict, tuple_type, cap: int = 64):
        self._fields = fields
        self._type = tuple_type
        self.arrays = allocate(fields, cap)
        self.n = 0
        self.slot_of: dict[int, int] = {}
        self._next_id = 1
        self.view = tuple_type(**self.arrays)

    @property
    def capacity(self) -> int:
        return len(self.arrays["id"])

    def _ensure(self, need: int) -> None:
        if need > self.capacity:
            cap = max(need, 2 * self.capacity)
            self.arrays = grown(self.arrays, cap)
            self.view = self._type(**self.arrays)

    def add(self) -> tuple[int, int]:
        """Append a zeroed entry; returns (id, slot)."""
        self._ensure(self.n + 1)
        s = self.n
        for a in self.arrays.values():
            a[s] = 0
        oid = self._next_id
        self._next_id += 1
        self.arrays["id"][s] = oid
        self.slot_of[oid] = s
        self.n += 1
        return oid, s

    def add_many(self, k: int) -> tuple[list, range]:
        """Append ``k`` zeroed entries at once (a chain's segments); returns (ids, slots), as ``k``
        calls of ``add`` would."""
        self._ensure(self.n + k)
        slots = range(self.n, self.n + k)
        for a in self.arrays.values():
            a[slots.start:slots.stop] = 0
        ids = list(range(self._next_id, self._next_id + k))
        self._next_id += k
        self.arrays["id"][slots.start:slots.stop] = ids
        self.slot_of.update(zip(ids, slots))
        self.n += k
        return ids, slots

    def remove(self, oid: int) -> tuple[int, int]:
        """Swap-remove; returns (removed slot, slot the last entry came from)."""
        s = self.slot_of.pop(oid)
        last = self.n - 1
        if s != last:
            for a in self.arrays.values():
                a[s] = a[last]
            self.slot_of[int(self.arrays["id"][s])] = s
        self.n -= 1
        return s, last

    def snapshot(self, names=None) -> dict:
        names = names or self.arrays.keys()
        return {k: self.arrays[k][: self.n].copy() for k in names}
