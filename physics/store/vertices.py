"""The vertex pool: vertices of all polygons in one array; holes are compacted lazily.

Vertices are stored relative to their body's centre of mass (where the
equations of motion live), counter-clockwise, with the outward normal of the
edge from each vertex to the next.  ``world`` and ``wnormal`` are refreshed
every step by the geometry stage.
"""
from __future__ import annotations

import numpy as np

from .table import ArraysSlot, allocate, f8, grown
from .table_view import view_class

VERT_FIELDS = {
    "local": ((2,), f8),    # vertex relative to the centre of mass, CCW order
    "normal": ((2,), f8),   # outward unit normal of edge i -> i+1, body frame
    "world": ((2,), f8),    # vertex in world coordinates (refreshed each step)
    "wnormal": ((2,), f8),  # edge normal in world coordinates
}
Verts = view_class("Verts", VERT_FIELDS, "verts")


class VertexPool:
    """Vertices of all polygons in one array; holes are compacted lazily."""

    arrays = ArraysSlot()

    def __init__(self, cap: int = 256):
        self.arrays = allocate(VERT_FIELDS, cap)
        self.top = 0
        self.live = 0
        self.view = Verts(**self.arrays)

    def add(self, local: np.ndarray) -> int:
        """Append a polygon's vertices (CCW, relative to its body's centre of mass); returns the start."""
        k = len(local)
        if self.top + k > len(self.arrays["local"]):
            self.arrays = grown(self.arrays, max(self.top + k, 2 * len(self.arrays["local"])))
            self.view = Verts(**self.arrays)
        s = self.top
        self.top += k
        self.live += k
        self.set(s, local)
        return s

    def add_many(self, polygons: list) -> np.ndarray:
        """Append several polygons at once (a chain's 100,000 segments: one numpy pass, not one call
        each); returns their starts.  The normals are those ``add`` gives, to the bit."""
        if len(polygons) == 1:  # one body's shape: the same numbers without the batch's bookkeeping
            return np.array([self.add(polygons[0])], np.int64)
        counts = np.array([len(p) for p in polygons], dtype=np.int64)
        total = int(counts.sum())
        if self.top + total > len(self.arrays["local"]):
            self.arrays = grown(self.arrays, max(self.top + total, 2 * len(self.arrays["local"])))
            self.view = Verts(**self.arrays)
        local = np.concatenate(polygons) if polygons else np.zeros((0, 2))
        ends = np.cumsum(counts)
        starts = ends - counts
        nxt = np.arange(1, total + 1)
        nxt[ends - 1] = starts  # each polygon's last vertex wraps to its first, as np.roll does
        e = local[nxt] - local
        nrm = np.stack([e[:, 1], -e[:, 0]], axis=1)
        nrm /= np.hypot(nrm[:, 0], nrm[:, 1])[:, None]
        s = self.top
        self.arrays["local"][s:s + total] = local
        self.arrays["normal"][s:s + total] = nrm
        self.top += total
        self.live += total
        return starts + s

    def set(self, s: int, local: np.ndarray) -> None:
        """Overwrite the vertices at ``s`` (same count) and their edge normals, e.g. after the
        body's centre of mass moved."""
        local = np.asarray(local, dtype=np.float64)
        k = len(local)
        self.arrays["local"][s:s + k] = local
        # the edge to the next vertex, the last to the first (np.roll's, without its copies)
        e = np.empty_like(local)
        np.subtract(local[1:], local[:-1], out=e[:-1])
        np.subtract(local[0], local[-1], out=e[-1])
        nrm = self.arrays["normal"][s:s + k]
        nrm[:, 0] = e[:, 1]
        nrm[:, 1] = -e[:, 0]
        nrm /= np.hypot(nrm[:, 0], nrm[:, 1])[:, None]

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
