"""physics.geometry.simplicity: the plane sweep that tells a simple polygon from one whose edges
meet agrees with testing every pair of edges, on random polygons drawn on a small integer grid
(so vertices on edges, collinear overlaps, vertical edges and repeated points are common), and it
scales as O(n log n): the 10,000-vertex outlines that took minutes are decided in well under a
second each."""
import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from physics.geometry.decompose import _turning
from physics.geometry.simplicity import _meet, first_meeting


def brute(points):
    n = len(points)
    for i in range(n):
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue
            if _meet(points[i], points[(i + 1) % n], points[j], points[(j + 1) % n]):
                return True
    return False


def prepared(raw):
    """Consecutive duplicates and straight vertices removed (first_meeting's precondition)."""
    pts = [tuple(map(float, p)) for k, p in enumerate(raw) if p != raw[k - 1]]
    if len(pts) < 3:
        return None
    pts = [pts[i] for i in _turning(pts)]
    if len(pts) < 3 or any(pts[k] == pts[k - 1] for k in range(len(pts))):
        return None
    return pts


@settings(max_examples=600, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 4), st.integers(0, 4)), min_size=3, max_size=12))
def test_the_sweep_agrees_with_every_pair(raw):
    pts = prepared(raw)
    if pts is None:
        return
    found = first_meeting(pts)
    assert (found is not None) == brute(pts)
    if found:
        i, j = found
        n = len(pts)
        assert _meet(pts[i], pts[(i + 1) % n], pts[j], pts[(j + 1) % n])


def star(n, wobble=0.4):
    a = np.linspace(0, 2 * math.pi, n, endpoint=False)
    r = np.where(np.arange(n) % 2 == 0, 1.0, 1.0 - wobble)
    return np.c_[r * np.cos(a), r * np.sin(a)].tolist()


def comb(teeth, horizontal=False):
    pts = [(0.0, 0.0)]
    for k in range(teeth):
        pts += [(2.0 * k + 1, 0.0), (2.0 * k + 1, 100.0), (2.0 * k + 2, 100.0), (2.0 * k + 2, 0.0)]
    pts += [(2.0 * teeth + 1, 0.0), (2.0 * teeth + 1, -1.0), (0.0, -1.0)]
    pts = pts[::-1]  # counter-clockwise does not matter here; keep it a valid simple outline
    return [(y, x) for x, y in pts] if horizontal else pts


def test_large_outlines_are_decided():
    for pts in (star(10_000), comb(2_500), comb(2_500, horizontal=True)):
        assert first_meeting(pts) is None
    crossed = comb(2_500)
    crossed[5000] = (crossed[5000][0], -5.0)  # one tooth pushed through the base
    assert first_meeting(crossed) is not None
