"""The query state of a world: its fixtures' current world geometry and their tree.

Built on the first query after a step or an edit and reused until the next one, so a burst of
queries between steps (a game's rays, the sandbox's pointer) pays the build once.  The key is
what can move a fixture: the step count, the pipeline's edit count (every setter and
add/remove calls Pipeline.invalidate) and the table sizes.
"""
from __future__ import annotations

from collections import namedtuple

import numpy as np

from .tree import build_tree
from .world_shapes import world_shapes


#: the fixture columns the query kernels read (sensors are skipped: filter.accepts); views of the table's arrays, so filter edits are seen.
#: Passing these six instead of the table's twenty columns cuts a kernel call's unboxing cost
#: (each array argument costs ~0.2 us to unbox; a one-ray cast from Python is mostly call cost).
QueryFixtures = namedtuple("QueryFixtures", ["shape", "radius", "vstart", "vcount", "category", "mask", "sensor"])


class QueryState:
    """World-space geometry (``wv``, ``wn``, ``wc``, ``box``), tree (``nb``, ``info``, ``order``) and
    the fixture columns the walks read (``qf``)."""

    __slots__ = ("key", "nf", "qf", "wv", "wn", "wc", "box", "nb", "info", "order", "slots", "ts", "ns")

    def __init__(self, world, key):
        st = world._store
        self.key = key
        nf = st.fixtures.n
        self.nf = nf
        F = st.fixtures.view
        self.qf = QueryFixtures(F.shape, F.radius, F.vstart, F.vcount, F.category, F.mask, F.sensor)
        V = st.verts.view
        nv = len(V.local)
        self.wv = np.zeros((nv, 2))
        self.wn = np.zeros((nv, 2))
        self.wc = np.zeros((max(nf, 1), 2))
        self.box = np.zeros((max(nf, 1), 4))
        world_shapes(st.bodies.view, st.fixtures.view, V, nf, self.wv, self.wn, self.wc, self.box)
        self.nb, self.info, self.order = build_tree(self.box, nf)
        # scratch for the hit lists (at most one hit per fixture)
        self.slots = np.empty(max(nf, 1), np.int32)
        self.ts = np.empty(max(nf, 1))
        self.ns = np.empty((max(nf, 1), 2))


def query_state(world) -> QueryState:
    """The world's current QueryState (rebuilt only when something may have moved)."""
    st = world._store
    key = (world.steps, world._pipeline.edits, st.bodies.n, st.fixtures.n, id(st.verts.arrays["local"]))
    qs = getattr(world, "_query_state", None)
    if qs is None or qs.key != key:
        qs = QueryState(world, key)
        world._query_state = qs
    return qs
