"""A record of arrays of different lengths in two buffers (physics/store/segments.py): compiled
code reads and writes the same memory as the Python views, 1-D and 2-D fields alike, and a kernel
call passes the two buffers only."""
import numpy as np
from numba import njit, typeof

from physics.store.segments import FLOAT, INT, SegmentsType, segments_class

Rec = segments_class("Rec", {"n": (INT, 0), "pairs": (INT, 3), "w": (FLOAT, 0), "empty": (FLOAT, 0)}, "test_rec")


@njit
def _touch(R):
    """Reads every field's shape and writes one item of each."""
    R.n[0] = R.pairs.shape[0] * 100 + R.pairs.shape[1] * 10 + R.w.shape[0]
    R.pairs[1, 2] = 7
    R.w[R.w.shape[0] - 1] = 2.5
    return R.empty.shape[0], R.n[1] + R.pairs[0, 1], R.w[0]


def test_fields_are_views_of_two_buffers_that_compiled_code_shares():
    r = Rec(n=2, pairs=4, w=5, empty=0)
    assert r.pairs.shape == (4, 3) and r.w.shape == (5,) and r.empty.shape == (0,)
    assert len(r._sources) == 2 and r.n.base is r._sources[0] and r.w.base is r._sources[1]
    r.n[1], r.pairs[0, 1], r.w[0] = 40, 2, -1.5
    assert _touch(r) == (0, 42, -1.5)
    assert r.n[0] == 435 and r.pairs[1, 2] == 7 and r.w[4] == 2.5
    assert r.pairs[1].tolist() == [0, 0, 7] and r.n[1] == 40  # nothing else written
    assert r.rows() == {"n": 2, "pairs": 4, "w": 5, "empty": 0}


def test_the_type_holds_the_buffers_only_and_depends_on_the_layout_not_the_sizes():
    a, b = Rec(n=1, pairs=1, w=1, empty=1), Rec(n=9, pairs=30, w=2, empty=0)
    ta = typeof(a)
    assert isinstance(ta, SegmentsType) and ta == typeof(b) and hash(ta) == hash(typeof(b))
    assert len(ta.sources) == 2  # what a call passes: two arrays, whatever the field count
    Other = segments_class("Other", {"n": (INT, 0), "w": (FLOAT, 0)}, "test_other")
    assert typeof(Other(n=1, w=1)) != ta
