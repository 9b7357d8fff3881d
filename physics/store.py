"""Structure-of-arrays state: bodies, the vertex pool, springs.

Every field is one numpy array of a shared capacity; live entries occupy the
dense range ``0..n-1`` so kernels loop over ``range(n)`` without holes.
Removal swaps the last entry into the hole, so a body's *slot* can change; the
stable handle is its *id*, mapped to a slot by ``slot_of``.  Kernels receive
the arrays as one namedtuple (one argument, unboxed once per call).

Positions are stored at the centre of mass (``x``) because that is where the
equations of motion live; ``com`` (body coordinates) converts to and from the
body origin that users see.  Vertices in the pool are relative to the centre
of mass for the same reason.
"""
from __future__ import annotations

from collections import namedtuple

import numpy as np

DYNAMIC, STATIC, KINEMATIC = 0, 1, 2
KINDS = {"dynamic": DYNAMIC, "static": STATIC, "kinematic": KINEMATIC}
KIND_NAMES = {v: k for k, v in KINDS.items()}
POLYGON, CIRCLE = 0, 1

f8, i1, i4, i8 = np.float64, np.int8, np.int32, np.int64

# name: (per-entry shape, dtype)
BODY_FIELDS = {
    "x": ((2,), f8),        # centre of mass, world
    "q": ((), f8),          # angle (rad)
    "v": ((2,), f8),        # velocity of the centre of mass
    "w": ((), f8),          # angular velocity (rad/s, CCW positive)
    "m": ((), f8),          # mass (computed from density even for static bodies)
    "inertia": ((), f8),    # moment of inertia about the centre of mass
    "inv_m": ((), f8),      # 0 for static and kinematic bodies
    "inv_i": ((), f8),
    "density": ((), f8),
    "kind": ((), i1),       # DYNAMIC / STATIC / KINEMATIC
    "e": ((), f8),          # restitution
    "mu_s": ((), f8),       # static friction coefficient
    "mu_d": ((), f8),       # dynamic friction coefficient
    "shape": ((), i1),      # POLYGON / CIRCLE
    "radius": ((), f8),     # circle radius (0 for polygons)
    "vstart": ((), i4),     # first vertex in the pool (polygons)
    "vcount": ((), i4),     # vertex count (0 for circles)
    "com": ((2,), f8),      # centre of mass in body coordinates (origin -> com)
    "bound_r": ((), f8),    # radius of the bounding circle about the centre of mass
    "aabb": ((4,), f8),     # min x, min y, max x, max y (fattened by the speculative margin)
    "awake": ((), i1),      # 1 awake, 0 asleep
    "sleep_t": ((), f8),    # time spent below the sleep velocity thresholds
    "island": ((), i4),     # island label while asleep (-1 awake)
    "f": ((2,), f8),        # user force accumulator, cleared every step
    "tau": ((), f8),        # user torque accumulator
    "id": ((), i8),         # stable id (handle)
}
VERT_FIELDS = {
    "local": ((2,), f8),    # vertex relative to the centre of mass, CCW order
    "normal": ((2,), f8),   # outward unit normal of edge i -> i+1, body frame
    "world": ((2,), f8),    # vertex in world coordinates (refreshed each step)
    "wnormal": ((2,), f8),  # edge normal in world coordinates
}
SPRING_FIELDS = {
    "a": ((), i4),          # body slot
    "b": ((), i4),          # body slot, or -1 for a world anchor
    "la": ((2,), f8),       # anchor on a, relative to a's centre of mass (body frame)
    "lb": ((2,), f8),       # anchor on b likewise, or the world point when b == -1
    "k": ((), f8),          # stiffness N/m
    "c": ((), f8),          # damping N s/m along the spring axis
    "rest": ((), f8),       # rest length m
    "id": ((), i8),
}

Bodies = namedtuple("Bodies", list(BODY_FIELDS))
Verts = namedtuple("Verts", list(VERT_FIELDS))
Springs = namedtuple("Springs", list(SPRING_FIELDS))


def allocate(fields: dict, cap: int) -> dict:
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


class VertexPool:
    """Vertices of all polygons in one array; holes are compacted lazily."""

    def __init__(self, cap: int = 256):
        self.arrays = allocate(VERT_FIELDS, cap)
        self.top = 0
        self.live = 0
        self.view = Verts(**self.arrays)

    def add(self, local: np.ndarray) -> int:
        k = len(local)
        if self.top + k > len(self.arrays["local"]):
            self.arrays = grown(self.arrays, max(self.top + k, 2 * len(self.arrays["local"])))
            self.view = Verts(**self.arrays)
        s = self.top
        self.arrays["local"][s:s + k] = local
        e = np.roll(local, -1, axis=0) - local
        nrm = np.stack([e[:, 1], -e[:, 0]], axis=1)
        nrm /= np.hypot(nrm[:, 0], nrm[:, 1])[:, None]
        self.arrays["normal"][s:s + k] = nrm
        self.top += k
        self.live += k
        return s

    def release(self, count: int) -> None:
        self.live -= count

    def needs_compaction(self) -> bool:
        return self.top > 1024 and self.live < self.top // 2

    def compact(self, vstart: np.ndarray, vcount: np.ndarray, n: int) -> None:
        """Move live ranges to the front; rewrites ``vstart`` in place."""
        order = np.argsort(vstart[:n], kind="stable")
        dst = 0
        for i in order:
            c = int(vcount[i])
            if c == 0:
                continue
            src = int(vstart[i])
            for a in self.arrays.values():
                a[dst:dst + c] = a[src:src + c].copy()
            vstart[i] = dst
            dst += c
        self.top = dst
        self.live = dst
