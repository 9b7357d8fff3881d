"""Sort and sweep in bands: linear in the body count for packed scenes.

A plain sort-and-sweep along one axis tests every pair whose projections on
that axis overlap; in a square pile or pyramid that is a whole column per
body, O(n^1.5) in all.  Cutting the other axis into bands a few bodies tall
and sweeping each band separately bounds the tests per body by the band's
population (the "segmented" SAP of Tracy et al., "Efficient large-scale
sweep and prune methods with AABB insertion and removal", IEEE VR 2009).

Bodies spanning several bands are entered in each; a pair is reported only in
the band holding the lower edge of its overlap, max(lo_i, lo_j), so exactly
once.  The sweep axis is the one with the larger spread of box centres; the
order along it is kept between calls and repaired by insertion sort, which is
linear when bodies move little per step (Baraff 1992, "Dynamic simulation of
non-penetrating rigid bodies", ch. 6), with a sort from scratch as fallback.
"""
from __future__ import annotations

import math

import numpy as np
from numba import prange

from ..._jit import kernel
from ...threads import MIN_BODIES, share
from ...store import STATIC
from ..argsort import argsort_into
from .filter import can_pair, overlap, push
from .order import sort_pairs

# band height in typical box extents: 2 keeps a body's band to about three
# rows of neighbours while a body rarely spans more than two bands
BAND_EXTENTS = 2.0
# boxes the typical extent is estimated from (evenly spaced slots): the bands
# only pace the sweep, the pairs found are the same for any band height
EXTENT_SAMPLE = 256
# at most this many boxes not resting: each is tested against every box instead of sweeping
# (a test costs ~2 ns here, the sweep ~40 ns a box: it pays below ~20 awake boxes)
FEW_AWAKE = 16


@kernel
def _finite(aabb, i):
    return (math.isfinite(aabb[i, 0]) and math.isfinite(aabb[i, 1])
            and math.isfinite(aabb[i, 2]) and math.isfinite(aabb[i, 3]))


@kernel
def _pick_axis(aabb, n):
    lo0 = math.inf
    hi0 = -math.inf
    lo1 = math.inf
    hi1 = -math.inf
    for i in range(n):
        if not _finite(aabb, i):
            continue
        cx = aabb[i, 0] + aabb[i, 2]
        cy = aabb[i, 1] + aabb[i, 3]
        lo0 = min(lo0, cx)
        hi0 = max(hi0, cx)
        lo1 = min(lo1, cy)
        hi1 = max(hi1, cy)
    return 0 if hi0 - lo0 >= hi1 - lo1 else 1


@kernel
def _less(key, a, b):
    # ties broken by slot so the order is unique whatever it started from
    return key[a] < key[b] or (key[a] == key[b] and a < b)


@kernel(runtime=True)
def _repair_order(order, key, n, fresh):
    """Sort slots by key; insertion sort from last call's order when it is
    nearly sorted, a full stable sort when not (or when ``fresh``)."""
    if not fresh:
        budget = 8 * n + 64
        moves = 0
        for a in range(1, n):
            x = order[a]
            b = a - 1
            while b >= 0 and _less(key, x, order[b]):
                order[b + 1] = order[b]
                b -= 1
            order[b + 1] = x
            moves += a - 1 - b
            if moves > budget:
                fresh = True
                break
    if fresh:
        argsort_into(key, n, order, np.empty(n, np.int64))


@kernel
def _band_span(lo, hi, origin, scale, nb):
    b0 = min(max(int((lo - origin) * scale), 0), nb - 1)
    b1 = min(max(int((hi - origin) * scale), 0), nb - 1)
    return b0, b1


@kernel
def _choose_bands(aabb, n, perp, b0, b1):
    """Band count and span per body; total entries stay below 3n."""
    lo = math.inf
    hi = -math.inf
    logsum = 0.0
    m = 0
    for i in range(n):
        if _finite(aabb, i):
            lo = min(lo, aabb[i, perp])
            hi = max(hi, aabb[i, perp + 2])
            m += 1
    spread = hi - lo
    nb = 1
    if m > 8 and spread > 0.0:
        # geometric mean: one huge ground box must not set the band height
        floor = 1e-6 * spread
        sampled = 0
        for i in range(0, n, max(1, n // EXTENT_SAMPLE)):
            if _finite(aabb, i):
                logsum += math.log(max(aabb[i, perp + 2] - aabb[i, perp], floor))
                sampled += 1
        typical = math.exp(logsum / sampled) if sampled else spread
        nb = int(min(spread / (BAND_EXTENTS * typical), m // 2))
        nb = max(nb, 1)
    scale = nb / spread if spread > 0.0 else 0.0
    while True:
        total = 0
        for i in range(n):
            if _finite(aabb, i):
                s0, s1 = _band_span(aabb[i, perp], aabb[i, perp + 2], lo, scale, nb)
                b0[i] = s0
                b1[i] = s1
                total += s1 - s0 + 1
            else:  # non-finite boxes take part in nothing
                b0[i] = 1
                b1[i] = 0
        if total <= 3 * n or nb == 1:
            return nb, total
        nb = max(nb // 2, 1)
        scale = nb / spread


@kernel
def _fill_bands(order, n, b0, b1, nb, bstart, ent):
    """Bucket slots by band, keeping the sweep order inside each band."""
    for b in range(nb + 1):
        bstart[b] = 0
    for i in range(n):
        for b in range(b0[i], b1[i] + 1):
            bstart[b + 1] += 1
    for b in range(nb):
        bstart[b + 1] += bstart[b]
    for s in range(n):
        i = order[s]
        for b in range(b0[i], b1[i] + 1):
            ent[bstart[b]] = i
            bstart[b] += 1
    for b in range(nb, 0, -1):  # bstart[b] was pushed to the end of band b
        bstart[b] = bstart[b - 1]
    bstart[0] = 0


@kernel
def _resting(kind, awake, i):
    """Asleep or static: two resting boxes never pair (filter.can_pair)."""
    return awake[i] == 0 or kind[i] == STATIC


@kernel
def _next_active(B, nb, bstart, ent, nxt):
    """nxt[a]: the first entry at or after a in a's band that is not resting (its band's end if
    none), so that a resting box's scan visits only the boxes it can pair with."""
    for b in range(nb):
        nx = bstart[b + 1]
        for a in range(bstart[b + 1] - 1, bstart[b] - 1, -1):
            if not _resting(B.kind, B.awake, ent[a]):
                nx = a
            nxt[a] = nx


@kernel
def _sweep_bands(B, lo, hi, axis, b0, bstart, ent, nxt, tmp):
    """The pairs of bands lo..hi-1 into ``tmp`` (as many as fit); returns their count."""
    aabb = B.aabb
    kind = B.kind
    awake = B.awake
    k = np.int64(0)  # not a literal: push compiles once
    for b in range(lo, hi):
        end = bstart[b + 1]
        for a in range(bstart[b], end):
            i = ent[a]
            hi = aabb[i, axis + 2]
            resting = _resting(kind, awake, i)
            c = a + 1
            while c < end:
                if resting:  # a sleeping wall or the ground costs nothing against itself
                    c = nxt[c]
                    if c >= end:
                        break
                j = ent[c]
                if aabb[j, axis] > hi:
                    break
                # reported in the band where the overlap starts
                if max(b0[i], b0[j]) == b and overlap(aabb, i, j) and can_pair(kind, awake, i, j):
                    k = push(tmp, k, i, j)
                c += 1
    return k


@kernel(entry=True)
def sweep_pairs(B, n, state, order, key, b0, b1, bstart, ent, tmp, head, pairs):
    """Pairs sorted by (i, j) into ``pairs``; returns the total count.

    When the count exceeds ``tmp``/``pairs`` the caller grows both and calls
    again.  ``state`` = [n, axis] of the order kept from the last call.
    Scratch sizes: order/key/b0/b1 n, bstart n + 2, ent 6n (the bands' entries, then each
    entry's next active one), head n + 1.
    """
    k = sweep_emit(B, n, state, order, key, b0, b1, bstart, ent, tmp, None)
    if k <= tmp.shape[0] and k <= pairs.shape[0]:
        sort_pairs(tmp, k, n, head, pairs)
    return k


@kernel
def _sweep(B, nb, axis, b0, bstart, ent, nxt, tmp, nthr):
    """Every band's pairs into ``tmp``: split between ``nthr`` threads for many entries (None:
    the serial build, physics/threads.py), each thread a run of bands into its own part of
    ``tmp``, then the parts moved together.  The pairs are the same in any order, and the caller
    sorts them (order.sort_pairs): the same pairs, in the same order, for any thread count.  A
    part that overflows is swept again on one thread (its count is what the caller grows by)."""
    if nthr is not None:
        if nthr > 1 and bstart[nb] >= MIN_BODIES * nthr and nb >= nthr:
            k = _sweep_split(B, nb, axis, b0, bstart, ent, nxt, tmp, nthr)
            if k >= 0:
                return k
    return _sweep_bands(B, 0, nb, axis, b0, bstart, ent, nxt, tmp)


@kernel(parallel=True, runtime=True)
def _sweep_split(B, nb, axis, b0, bstart, ent, nxt, tmp, nthr):
    """_sweep's split: thread t sweeps the bands whose entries start in its share of them into
    tmp's t-th part; minus one when a part overflowed."""
    cut = np.empty(nthr + 1, np.int64)  # the bands' runs, even in entries
    cut[0] = 0
    b = 0
    for t in range(1, nthr):
        while b < nb and bstart[b] < share(bstart[nb], t, nthr)[0]:
            b += 1
        cut[t] = b
    cut[nthr] = nb
    cap = tmp.shape[0] // nthr
    got = np.empty(nthr, np.int64)
    for t in prange(nthr):
        got[t] = _sweep_bands(B, cut[t], cut[t + 1], axis, b0, bstart, ent, nxt, tmp[t * cap:(t + 1) * cap])
    k = got[0]
    for t in range(nthr):
        if got[t] > cap:
            return -1
    for t in range(1, nthr):
        for q in range(got[t]):
            tmp[k, 0] = tmp[t * cap + q, 0]
            tmp[k, 1] = tmp[t * cap + q, 1]
            k += 1
    return k


@kernel
def _few_awake(B, n):
    """Whether at most FEW_AWAKE boxes are not resting (then every pair has one of them)."""
    m = 0
    for i in range(n):
        if not _resting(B.kind, B.awake, i):
            m += 1
            if m > FEW_AWAKE:
                return False
    return True


@kernel
def _awake_pairs(B, n, tmp):
    """The sweep's pairs when few boxes are awake: each awake box against every other finite
    box, a pair of two awake boxes once (from the lower slot); returns their count."""
    aabb = B.aabb
    kind = B.kind
    awake = B.awake
    k = np.int64(0)
    for i in range(n):
        if _resting(kind, awake, i) or not _finite(aabb, i):
            continue
        for j in range(n):
            if j == i or (j < i and not _resting(kind, awake, j)):
                continue
            if _finite(aabb, j) and overlap(aabb, i, j) and can_pair(kind, awake, i, j):
                k = push(tmp, k, i, j)
    return k


@kernel
def sweep_emit(B, n, state, order, key, b0, b1, bstart, ent, tmp, nthr):
    """``sweep_pairs``' pairs in the sweep's order into ``tmp`` (as many as fit); returns the
    total count.  The caller may drop some before sorting what is left (order.sort_pairs).
    ``nthr``: _sweep's.  With a few boxes awake among many resting ones (a sleeping wall and
    its ram) the awake ones are tested against all instead: every pair has an awake box, and
    sorting and banding the resting ones would cost more than the whole test.  The same pairs;
    the kept order is repaired at the next sweep."""
    if _few_awake(B, n):
        return _awake_pairs(B, n, tmp)
    aabb = B.aabb
    axis = _pick_axis(aabb, n)
    for i in range(n):
        key[i] = aabb[i, axis] if _finite(aabb, i) else math.inf
    fresh = state[0] != n or state[1] != axis
    _repair_order(order, key, n, fresh)
    state[0] = n
    state[1] = axis
    nb, _ = _choose_bands(aabb, n, 1 - axis, b0, b1)
    _fill_bands(order, n, b0, b1, nb, bstart, ent)
    half = ent.shape[0] // 2
    _next_active(B, nb, bstart, ent, ent[half:])
    return _sweep(B, nb, axis, b0, bstart, ent, ent[half:], tmp, nthr)
