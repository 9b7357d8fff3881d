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

#: how many times any table's or vertex pool's arrays were replaced (growth, a restore), in any
#: world: the step driver keeps references to the arrays and checks this one number per step
#: instead of the identity of every table's arrays
GENERATION = [0]


class ArraysSlot:
    """The ``arrays`` attribute of a table: assigning it counts in GENERATION."""

    def __get__(self, obj, owner=None):
        return self if obj is None else obj._arrays

    def __set__(self, obj, value) -> None:
        obj._arrays = value
        GENERATION[0] += 1


class Columns(dict):
    """A table's fields (name -> array) as column views of two row-major 2-D arrays: ``F``
    (float64, one row per entry) and ``I`` (int64).  One entry's state is one row, as in Box2D
    v3's body and contact records, and a kernel can take the two arrays with named column
    constants instead of one argument per field (docs/flat-step.md).  Integer fields of any
    width are int64 columns; unsigned 64-bit ones (filter bits) are viewed as uint64.

    A field of two or more dimensions per entry (a chain segment's ghost vertices) is its own
    contiguous array in ``X``: compiled code can slice columns out of ``F`` but cannot reshape
    a strided slice, so store/flat.py could not rebuild such a view inside a kernel.  ``flat``
    is what a kernel takes for the whole table: ``(F, I, *X)``."""

    F: np.ndarray
    I: np.ndarray
    X: tuple
    flat: tuple
    spec: tuple


def separate(shape) -> bool:
    """Whether a field of this per-entry shape is its own array (``Columns.X``), not columns."""
    return len(shape) >= 2


#: F and I are at least this wide: a one-column array's column is contiguous, so numba would
#: type it 'C' where a column sliced inside a kernel is 'A' (two compiled versions of a kernel)
MIN_WIDTH = 2


def _columns(spec, cap: int) -> Columns:
    cols = [(name, shp, dt) for name, shp, dt in spec if not separate(shp)]
    nf = sum(int(np.prod(shp)) for _, shp, dt in cols if dt.kind == "f")
    ni = sum(int(np.prod(shp)) for _, shp, dt in cols if dt.kind != "f")
    out = Columns()
    out.F = np.zeros((cap, max(nf, MIN_WIDTH)))
    out.I = np.zeros((cap, max(ni, MIN_WIDTH)), np.int64)
    out.spec = spec
    extra = []
    fc = ic = 0
    for name, shp, dt in spec:
        if separate(shp):
            out[name] = np.zeros((cap,) + shp, dt)
            extra.append(out[name])
            continue
        w = int(np.prod(shp))
        if dt.kind == "f":
            base, c = out.F, fc
            fc += w
        else:
            base, c = out.I, ic
            ic += w
        view = base[:, c] if not shp else base[:, c:c + w].reshape((cap,) + shp)
        out[name] = view.view(np.uint64) if dt == np.uint64 else view
    out.X = tuple(extra)
    out.flat = (out.F, out.I) + out.X
    return out


def allocate(fields: dict, cap: int) -> Columns:
    """Zeroed fields (name: (per-entry shape, dtype)) with ``cap`` entries, as columns."""
    return _columns(tuple((k, tuple(shp), np.dtype(dt)) for k, (shp, dt) in fields.items()), cap)


def grown(arrays: Columns, cap: int) -> Columns:
    """The same fields with a larger first dimension (contents kept)."""
    out = _columns(arrays.spec, cap)
    for a, b in zip(out.flat, arrays.flat):
        a[:len(b)] = b
    return out


class Table:
    """A growable dense table of SoA fields with stable ids (swap-remove)."""

    arrays = ArraysSlot()

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
        for a in self.arrays.flat:  # every field is a view of these (Columns): a row each
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
        for a in self.arrays.flat:
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
            for a in self.arrays.flat:
                a[s] = a[last]
            self.slot_of[int(self.arrays["id"][s])] = s
        self.n -= 1
        return s, last

    def snapshot(self, names=None) -> dict:
        names = names or self.arrays.keys()
        return {k: self.arrays[k][: self.n].copy() for k in names}
