"""Every broad-phase method must report exactly the brute-force pairs, sorted.

The reference is a numpy all-pairs test written independently of the
kernels, with the interaction filter of docs/internals.md (stage 2).
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from physics.collision import broadphase as bp
from physics.collision.broadphase.sweep import FEW_AWAKE
from physics.store import BODY_FIELDS, DYNAMIC, KINEMATIC, STATIC, Bodies, allocate

METHODS = [m for m in bp.METHODS]


def bodies(boxes, kind=None, awake=None, spare=3):
    boxes = np.asarray(boxes, dtype=np.float64).reshape(-1, 4)
    n = len(boxes)
    B = Bodies(**allocate(BODY_FIELDS, n + spare))  # spare rows: kernels must stop at n
    B.aabb[:n] = boxes
    B.aabb[n:] = (-1e9, -1e9, 1e9, 1e9)
    B.kind[:n] = DYNAMIC if kind is None else kind
    B.awake[:n] = 1 if awake is None else awake
    return B, n


def reference(B, n):
    a = B.aabb[:n]
    ov = ((a[:, None, 0] <= a[None, :, 2]) & (a[None, :, 0] <= a[:, None, 2])
          & (a[:, None, 1] <= a[None, :, 3]) & (a[None, :, 1] <= a[:, None, 3]))
    k = B.kind[:n]
    w = B.awake[:n] != 0
    some_dynamic = (k[:, None] == DYNAMIC) | (k[None, :] == DYNAMIC)
    both_asleep = ~w[:, None] & ~w[None, :]
    asleep_static = (~w[:, None] & (k[None, :] == STATIC)) | (~w[None, :] & (k[:, None] == STATIC))
    keep = np.triu(ov & some_dynamic & ~both_asleep & ~asleep_static, 1)
    return np.argwhere(keep).astype(np.int32)  # row-major: sorted by (i, j)


def check_all(B, n, pairs_cap=4):
    want = reference(B, n)
    for m in METHODS:
        count, pairs = bp.find_pairs(B, n, m, np.zeros((pairs_cap, 2), np.int32))
        assert pairs.dtype == np.int32 and pairs.shape[1] == 2
        assert count == len(want), (m, count, len(want))
        np.testing.assert_array_equal(pairs[:count], want, err_msg=m)
    return want


# -- scenes ---------------------------------------------------------------
def _boxes_from(centres, halves):
    return np.concatenate([centres - halves, centres + halves], axis=1)


@st.composite
def scenes(draw):
    n = draw(st.integers(0, 90))
    layout = draw(st.sampled_from(["random", "grid", "identical", "line", "huge_tiny", "points"]))
    seed = draw(st.integers(0, 2**32 - 1))
    far = draw(st.sampled_from([0.0, 1e4, -1e4]))
    rng = np.random.default_rng(seed)
    if layout == "random":
        c = rng.uniform(-20, 20, (n, 2))
        h = rng.uniform(0, 3, (n, 2))
    elif layout == "grid":  # half-integer coordinates: many exactly touching edges
        c = rng.integers(-8, 8, (n, 2)) * 0.5
        h = rng.integers(0, 3, (n, 2)) * 0.25
    elif layout == "identical":
        c = np.tile(rng.uniform(-5, 5, 2), (n, 1))
        h = np.tile(rng.uniform(0, 2, 2), (n, 1))
    elif layout == "line":
        t = rng.uniform(-30, 30, n)
        d = rng.uniform(-1, 1, 2)
        c = t[:, None] * d[None, :]
        h = rng.uniform(0, 1, (n, 2))
    elif layout == "huge_tiny":
        c = rng.uniform(-50, 50, (n, 2))
        h = rng.choice([0.0, 1e-6, 0.5, 1e3], (n, 2))
    else:  # zero-size boxes on a coarse lattice: coincident points
        c = rng.integers(-3, 3, (n, 2)).astype(float)
        h = np.zeros((n, 2))
    boxes = _boxes_from(c + far, h)
    kind = rng.choice([DYNAMIC, DYNAMIC, STATIC, KINEMATIC], n)
    awake = rng.choice([0, 1, 1], n)
    if draw(st.booleans()):  # mostly asleep: around sweep.FEW_AWAKE boxes awake, or fewer
        awake[:] = 0
        awake[rng.choice(n, min(n, int(rng.integers(0, 2 * FEW_AWAKE))), replace=False)] = 1
    return boxes, kind, awake


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scenes(), st.integers(1, 64))
def test_methods_match_brute_force(scene, cap):
    B, n = bodies(*scene)
    check_all(B, n, cap)


@settings(max_examples=30, deadline=None)
@given(scenes(), st.floats(0.0, 0.3), st.integers(0, 2**32 - 1))
def test_coherent_calls_match_after_motion(scene, step, seed):
    """The sweep keeps its order between calls; small and large moves must both be right."""
    B, n = bodies(*scene)
    check_all(B, n)
    rng = np.random.default_rng(seed)
    B.aabb[:n] += np.repeat(rng.uniform(-step, step, (n, 2)), 2, axis=0).reshape(n, 4)
    check_all(B, n)
    B.aabb[:n] = B.aabb[rng.permutation(n)] if n else B.aabb[:n]  # slots reshuffled
    check_all(B, n)


@pytest.mark.parametrize("n_awake", [0, 1, 3, FEW_AWAKE, FEW_AWAKE + 1, 40])
def test_a_sleeping_wall_and_a_few_awake_boxes(n_awake):
    """A wall of 60 x 40 touching boxes asleep on a static floor and ``n_awake`` boxes woken in
    it (pairs among themselves and with sleepers): the few-awake test and the sweep report the
    reference's pairs, also on calls one after another as boxes wake (the kept order)."""
    rng = np.random.default_rng(n_awake)
    gx, gy = np.meshgrid(np.arange(60) * 0.5, np.arange(40) * 0.5)  # binary fractions: edges meet exactly
    c = np.c_[gx.ravel(), gy.ravel()]
    boxes = _boxes_from(np.r_[c, [[15.0, -1.0]]], np.r_[np.full((len(c), 2), 0.25), [[20.0, 0.75]]])
    n = len(boxes)
    kind = np.full(n, DYNAMIC)
    kind[-1] = STATIC
    awake = np.zeros(n, np.int64)
    for k in (0, n_awake // 2, n_awake):
        awake[rng.choice(n - 1, k, replace=False)] = 1
        B, n = bodies(boxes, kind, awake)
        want = check_all(B, n, 8)
        assert len(want) >= 2 * k  # every awake box touches its neighbours


def test_dense_pile_grows_the_buffer():
    """600 identical boxes: 179 700 pairs from a 4-row buffer, for every method."""
    B, n = bodies(np.tile([0.0, 0.0, 1.0, 1.0], (600, 1)))
    want = check_all(B, n, pairs_cap=4)
    assert len(want) == 600 * 599 // 2


def test_pyramid_with_ground_box():
    """A wide static ground under a pyramid: the layout that made plain SAP quadratic."""
    boxes = [(-400.0, -1.0, 400.0, 0.0)]
    for row in range(30):
        for k in range(30 - row):
            x, y = 0.5 * row + k, float(row)
            boxes.append((x - 0.01, y - 0.01, x + 1.01, y + 1.01))
    kind = np.zeros(len(boxes), np.int8)
    kind[0] = STATIC
    B, n = bodies(boxes, kind)
    want = check_all(B, n)
    assert ((want[:, 0] == 0).sum()) == 30  # the ground touches the bottom row only


def test_filter_rules():
    box = (0.0, 0.0, 1.0, 1.0)
    cases = [  # (kind a, awake a, kind b, awake b) -> reported
        ((DYNAMIC, 1, DYNAMIC, 1), True), ((DYNAMIC, 0, DYNAMIC, 1), True),
        ((DYNAMIC, 0, DYNAMIC, 0), False), ((DYNAMIC, 1, STATIC, 1), True),
        ((DYNAMIC, 0, STATIC, 1), False), ((DYNAMIC, 0, KINEMATIC, 1), True),
        ((STATIC, 1, KINEMATIC, 1), False), ((KINEMATIC, 1, KINEMATIC, 1), False),
        ((STATIC, 1, STATIC, 1), False), ((KINEMATIC, 1, DYNAMIC, 1), True),
    ]
    for (ka, wa, kb, wb), expect in cases:
        B, n = bodies([box, box], [ka, kb], [wa, wb])
        for m in METHODS:
            count, _ = bp.find_pairs(B, n, m, np.zeros((1, 2), np.int32))
            assert count == int(expect), (m, ka, wa, kb, wb)


def test_nan_box_is_ignored():
    B, n = bodies([(0, 0, 1, 1), (np.nan, 0, 1, 1), (0.5, 0.5, 2, 2)])
    for m in METHODS:
        count, pairs = bp.find_pairs(B, n, m, np.zeros((4, 2), np.int32))
        assert count == 1 and tuple(pairs[0]) == (0, 2), m


def test_auto_and_unknown_method():
    assert bp.resolve("auto", 1) == "brute"
    assert bp.resolve("auto", 10_000) == "sweep"
    with pytest.raises(ValueError, match="unknown broad-phase method"):
        bp.find_pairs(*bodies([(0, 0, 1, 1)]), "octree", np.zeros((1, 2), np.int32))


def test_quadtree_cells_cover_the_boxes():
    rng = np.random.default_rng(3)
    c = rng.uniform(0, 40, (400, 2))
    B, n = bodies(_boxes_from(c, np.full((400, 2), 0.5)))
    cells = bp.quadtree_cells(B, n)
    assert cells.ndim == 2 and cells.shape[1] == 4 and len(cells) > 1
    lo, hi = B.aabb[:n, :2].min(0), B.aabb[:n, 2:].max(0)
    np.testing.assert_array_equal(cells[0], np.concatenate([lo, hi]))  # root = union
    assert np.all(cells[:, :2] <= cells[:, 2:])
    assert bp.quadtree_cells(*bodies(np.empty((0, 4)))).shape == (0, 4)


def test_runs_without_jit():
    """The kernels are plain Python under NUMBA_DISABLE_JIT=1 (debugging path)."""
    code = (
        "import numpy as np, sys\n"
        "sys.path.insert(0, 'tests')\n"
        "from test_broadphase import bodies, check_all\n"
        "rng = np.random.default_rng(0)\n"
        "c = rng.uniform(0, 10, (60, 2))\n"
        "B, n = bodies(np.concatenate([c - 0.6, c + 0.6], 1))\n"
        "assert len(check_all(B, n, 2)) > 0\n"
    )
    root = Path(__file__).resolve().parents[1]
    env = dict(os.environ, NUMBA_DISABLE_JIT="1", PYTHONPATH=str(root))
    subprocess.run([sys.executable, "-c", code], cwd=root, env=env, check=True, timeout=120)
