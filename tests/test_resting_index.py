"""The broad phase of a mostly resting world (collision/broadphase/resting_index.py): a few awake
boxes queried against the sorted resting ones must report exactly the brute-force pairs, and the
one-call step must use it without changing a bit of a sleeping wall's run."""
from __future__ import annotations

import numba
import numpy as np
from hypothesis import HealthCheck, given, settings

from physics.collision.broadphase.resting_index import build_index, few_awake_of, indexed_pairs
from physics.collision.broadphase.sweep import FEW_AWAKE
from physics.store import DYNAMIC, STATIC
from test_broadphase import bodies, reference, scenes


@numba.njit(cache=False)
def _indexed(B, n, actf, nactf, cap):
    f = np.zeros(n + 1)
    o = np.zeros(n + 1, np.int64)
    t = np.zeros(n + 1, np.int64)
    rkey = np.zeros(n + 1)
    rslot = np.zeros(n + 1, np.int64)
    nrest, wide = build_index(B, n, f, o, t, rkey, rslot)
    tmp = np.zeros((cap, 2), np.int32)
    k = indexed_pairs(B, actf, nactf, rkey, rslot, nrest, wide, tmp)
    return few_awake_of(B, actf, nactf), k, tmp


def _pairs(B, n, cap):
    """(few awake?, the index's pairs sorted, its count) with every non-static box listed as the
    step lists the fixtures that can be awake (step/active.py)."""
    actf = np.flatnonzero(B.kind[:n] != STATIC).astype(np.int64)
    few, k, tmp = _indexed(B, n, actf, len(actf), cap)
    got = tmp[:min(k, cap)]
    got = np.sort(got, axis=1)
    return few, got[np.lexsort((got[:, 1], got[:, 0]))], k


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scenes())
def test_index_pairs_match_brute_force_when_few_are_awake(scene):
    B, n = bodies(*scene)
    resting = (B.awake[:n] == 0) | (B.kind[:n] == STATIC)
    awake = int((~resting).sum())
    few, got, k = _pairs(B, n, 4 * n * n + 4)
    assert few == (awake <= FEW_AWAKE)
    if few:
        want = reference(B, n)
        assert k == len(want)
        np.testing.assert_array_equal(got, want)


def test_a_sleeping_wall_with_boxes_of_every_width():
    """Resting boxes from 1 cm to 30 m wide (the widest sets how far back a query starts) and
    ten awake boxes among them: every pair found."""
    rng = np.random.default_rng(7)
    n = 400
    lo = np.c_[rng.uniform(-50, 50, n), rng.uniform(-1, 1, n)]
    size = np.c_[rng.choice([0.01, 0.5, 2.0, 30.0], n), rng.uniform(0.01, 1.0, n)]
    boxes = np.c_[lo, lo + size]
    kind = np.where(rng.uniform(size=n) < 0.2, STATIC, DYNAMIC)
    awake = np.zeros(n, np.int64)
    awake[rng.choice(n, 10, replace=False)] = 1
    B, n = bodies(boxes, kind, awake)
    few, got, k = _pairs(B, n, 100000)
    want = reference(B, n)
    assert few and k == len(want) and len(want) > 20
    np.testing.assert_array_equal(got, want)
