"""Broad phase: slot pairs whose fattened AABBs overlap (docs/internals.md, stage 2).

``find_pairs(B, n, method, pairs)`` is the one entry point the pipeline
calls, with the fixture table (store/fixtures.py: per-fixture AABBs and the
body's kind and awake flag mirrored; fixture_filter.py then drops pairs of one
body and filtered pairs); any table with ``aabb``, ``kind`` and ``awake`` works.  Every method returns the same pairs in the same order (ascending
(i, j)), so switching method never changes a simulation.  Scratch arrays live
here between calls and grow on demand; they are shared by all worlds, so the
broad phase is not re-entrant across threads.
"""
from __future__ import annotations

import numpy as np

from ...options import BROADPHASES
from .brute import brute_pairs, brute_pairs_flat
from .limit import MAX_PAIRS, check_pairs
from .quadtree import build as _build_quadtree
from .quadtree import quadtree_pairs
from .sweep import sweep_pairs

METHODS = BROADPHASES

# "auto" uses brute force below this many bodies and sweep from here on.
# Measured with `python -m bench.collision` (random boxes and pyramids, 2-core
# VM): the two cost the same (10-25 us per call, mostly call overhead) between
# about 100 and 190 bodies; above that brute force grows quadratically (0.37-0.7
# ms at 1k vs 0.04-0.07 for sweep).  Quadtree was slower than sweep at every size.
AUTO_BRUTE_BELOW = 128


class _Scratch:
    """Work arrays kept across calls so steady-state steps allocate nothing."""

    def __init__(self):
        self.cap = 0
        self.state = np.full(2, -1, np.int64)
        self.tmp = np.empty((0, 2), np.int32)
        self.qt_reg = np.empty((0, 4), np.float64)
        self.qt_info = np.empty((0, 3), np.int32)
        self.qt_items = np.empty(0, np.int32)
        self.qt_box = np.empty((0, 4), np.float64)
        self._bodies(64)

    def _bodies(self, cap):
        self.cap = cap
        self.order = np.arange(cap, dtype=np.int32)
        self.key = np.empty(cap, np.float64)
        self.b0 = np.empty(cap, np.int32)
        self.b1 = np.empty(cap, np.int32)
        self.bstart = np.empty(cap + 2, np.int32)
        self.ent = np.empty(6 * cap, np.int32)
        self.head = np.empty(cap + 1, np.int32)
        self.state[:] = -1  # the kept order no longer matches

    def ensure(self, n, npairs):
        if n > self.cap:
            self._bodies(max(n, 2 * self.cap))
        if npairs > len(self.tmp):
            self.tmp = np.empty((npairs, 2), np.int32)


_S = _Scratch()


def resolve(method: str, n: int) -> str:
    """The concrete method ``find_pairs`` will run for ``n`` bodies."""
    if method not in METHODS:
        raise ValueError(f"unknown broad-phase method {method!r}; choose one of {METHODS}")
    if method == "auto":
        return "brute" if n < AUTO_BRUTE_BELOW else "sweep"
    return method


def _run(B, n, method, pairs, flat):
    if method == "brute":
        return brute_pairs(B, n, pairs) if flat is None else brute_pairs_flat(*flat, n, pairs)
    if method == "sweep":
        return sweep_pairs(B, n, _S.state, _S.order, _S.key, _S.b0, _S.b1, _S.bstart,
                           _S.ent, _S.tmp, _S.head, pairs)
    k, _S.qt_reg, _S.qt_info, _S.qt_items, _S.qt_box = quadtree_pairs(
        B, n, _S.qt_reg, _S.qt_info, _S.qt_items, _S.qt_box, _S.tmp, _S.head, pairs)
    return k


def find_pairs(B, n, method, pairs, limit=MAX_PAIRS, flat=None):
    """Interacting overlapping pairs (i < j), sorted; returns (count, pairs).

    ``B``: the fixture table's view (fields ``aabb``, ``kind``, ``awake``); ``flat``: the same
    table's flat arrays (``Table.arrays.flat``), which a small world's brute-force pass takes
    instead: its call then unboxes two arrays, not the whole view (store/flat.py).

    ``pairs`` is an int32 (P, 2) buffer; when the pairs do not fit, a larger
    buffer is made, filled by one more kernel call, and returned.  More than
    ``limit`` pairs is SimulationError, before anything is allocated for them
    (limit.py).
    """
    m = resolve(method, n)
    _S.ensure(n, len(pairs))
    count = int(_run(B, n, m, pairs, flat))
    check_pairs(count, limit, n)
    if count > len(pairs):
        pairs = np.empty((count + count // 2 + 16, 2), np.int32)
        _S.ensure(n, len(pairs))
        count = int(_run(B, n, m, pairs, flat))
    return count, pairs


def quadtree_cells(B, n):
    """Rectangles (K, 4) of the quadtree's nodes, for the sandbox's debug overlay.

    The root is unbounded; rectangles are clipped to the union of the AABBs.
    """
    if n == 0:
        return np.empty((0, 4), np.float64)
    _S.ensure(n, 0)
    _, nodes, _S.qt_reg, _S.qt_info, _S.qt_items, _S.qt_box = _build_quadtree(
        B, n, _S.qt_reg, _S.qt_info, _S.qt_items, _S.qt_box, _S.tmp, False)
    box = B.aabb[:n]
    ok = np.all(np.isfinite(box), axis=1)
    if not ok.any():
        return np.empty((0, 4), np.float64)
    lo = box[ok, :2].min(axis=0)
    hi = box[ok, 2:].max(axis=0)
    cells = _S.qt_reg[:nodes].copy()
    cells[:, :2] = np.clip(cells[:, :2], lo, hi)
    cells[:, 2:] = np.clip(cells[:, 2:], lo, hi)
    return cells


resolve_method = resolve  # the name the pipeline's `info` looks for
