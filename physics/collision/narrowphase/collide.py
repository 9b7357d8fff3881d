"""The narrow phase's pass over every broad-phase pair, on one thread or split between several.

kernel.py computes the rows of a run of pairs (``_rows``); this module runs it over all of them.
Split between threads (physics/threads.py), each thread takes a contiguous run of the pairs in
key order and writes its rows from the slot of its first pair on (a pair makes at most one row,
so the runs cannot overlap); the runs are then moved down to close the gaps, in order.  Every
pair is computed as on one thread, and the rows come out in the same order: the same bits for
any thread count.
"""
from __future__ import annotations

import numpy as np
from numba import prange

from ..._jit import kernel
from ...store.flat import bodies_view, contacts_view, fixtures_view, verts_view
from ...threads import MIN_PAIRS, share
from .carry import move_row
from .kernel import _order_into, _rows, manifold_scratch, pair_keys


@kernel(runtime=True)
def collide_kernel(ctx, B, F, V, pairs, npairs, C, P, n_prev, full=None):
    """Fill C (rows sorted by key, point state carried over from P); returns the row count, or
    -1 when ``full`` is None (the lean kernel: kernel._manifold) and a pair needs the whole kernel.

    ``ctx``: the step context (physics/step/context.py: dt, spec, narrowphase, threads); ``full``:
    None for the lean kernel (the narrow phase must be SAT), any integer for the whole one.

    Allocates the sort order and the scratch once per call; the per-pair work is kernel._rows.
    """
    keys = pair_keys(F, pairs, npairs)
    order = np.empty(npairs, np.int64)
    _order_into(keys, npairs, order)
    return collide_with(ctx, B, F, V, pairs, npairs, C, P, n_prev, full, keys, order, manifold_scratch(), None)


@kernel
def collide_with(ctx, B, F, V, pairs, npairs, C, P, n_prev, full, keys, order, scratch, nthr):
    """``collide_kernel`` with the pairs' ``keys`` and ``order[:npairs]`` given and the manifold
    ``scratch`` (manifold_scratch's arrays) reused: the step driver keeps them between steps;
    split between ``nthr`` threads for many pairs (None: the serial build, physics/threads.py)."""
    sc_a, sc_b, sw, si, lam, poly, out_p, out_s, out_f = scratch
    c = ctx[0]
    if nthr is not None:
        if nthr > 1 and npairs >= MIN_PAIRS * nthr:
            return _rows_split(ctx, B, F, V, pairs, order[:npairs], keys, C, P, n_prev, full, nthr)
    zero = np.int64(0)  # not a literal: _rows compiles once
    return _rows(B, F, V, pairs, order[:npairs], keys, C, P, n_prev, c.narrowphase, full, c.dt, c.spec, zero, zero,
                 sc_a, sc_b, sw, si, lam, poly, out_p, out_s, out_f)


@kernel(parallel=True, runtime=True)
def _rows_split(ctx, B, F, V, pairs, order, keys, C, P, n_prev, full, nthr):
    """``_rows`` over ``order`` in one run per thread, each with its own scratch; the runs' rows
    then moved down into one sorted block.  -1 when any run met a pair the lean kernel leaves out."""
    n = order.shape[0]
    ends = np.empty(nthr, np.int64)
    for t in prange(nthr):
        c = ctx[0]
        lo, hi = share(n, t, nthr)
        # the previous step's rows are sorted by key: the run's first is found by bisection
        ptr = np.searchsorted(P.key[:n_prev], keys[order[lo]]) if hi > lo else 0
        sc_a, sc_b, sw, si, lam, poly, out_p, out_s, out_f = manifold_scratch()
        ends[t] = _rows(B, F, V, pairs, order[lo:hi], keys, C, P, n_prev, c.narrowphase, full, c.dt, c.spec, lo,
                        ptr, sc_a, sc_b, sw, si, lam, poly, out_p, out_s, out_f)
    for t in range(nthr):
        if ends[t] < 0:
            return -1
    row = ends[0]
    for t in range(1, nthr):
        for r in range(share(n, t, nthr)[0], ends[t]):
            move_row(C, row, r)
            row += 1
    return row


@kernel(entry=True, runtime=True)
def collide_flat(ctx, BF, BI, FF, FI, ghost, wghost, VF, VI, pairs, npairs, CF, CI, Cpt, PF, PI, Ppt, n_prev,
                 full=None):
    """``collide_kernel`` over the tables' flat arrays (store/flat.py)."""
    return collide_kernel(ctx, bodies_view(BF, BI), fixtures_view(FF, FI, ghost, wghost), verts_view(VF, VI),
                          pairs, npairs, contacts_view(CF, CI, Cpt), contacts_view(PF, PI, Ppt), n_prev, full)
