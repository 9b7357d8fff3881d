"""Which sensor pairs overlap: the exact shapes, not their boxes.

Each (sensor, visitor) pair of the broad phase runs the narrow phase's own shape dispatch
(kernel._manifold) with no margin: the shapes overlap when it finds a point of negative
separation.  Geometry is the step's (the start-of-step positions the contacts are found at).
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel
from ...geometry.shapes import MAX_POLYGON_VERTICES
from .kernel import _manifold


@kernel
def sensor_overlaps(ctx, B, F, V, spairs, ns, out):
    """Write the keys (sensor id << 32) | visitor id of the overlapping pairs of ``spairs[:ns]``
    to ``out``; returns their count (in pair order)."""
    sc_a = np.empty((MAX_POLYGON_VERTICES, 2))
    sc_b = np.empty((MAX_POLYGON_VERTICES, 2))
    sw = np.empty((3, 2))
    si = np.empty((3, 2), np.int64)
    lam = np.empty(3)
    poly = np.empty((2 * MAX_POLYGON_VERTICES + 4, 2))
    out_p = np.zeros((2, 2))
    out_s = np.zeros(2)
    out_f = np.zeros(2, np.int32)
    method = ctx[0].narrowphase
    k = 0
    for p in range(ns):
        s = spairs[p, 0]
        v = spairs[p, 1]
        # the orientation the contacts use (lower id first), so a pair is computed one way only
        fa, fb = (s, v) if F.id[s] < F.id[v] else (v, s)
        count, nx, ny = _manifold(B, F, V, fa, fb, F.body[fa], F.body[fb], method, 0.0, sc_a, sc_b, sw, si, lam,
                                  poly, out_p, out_s, out_f)
        hit = False
        for q in range(count):
            hit = hit or out_s[q] < 0.0
        if hit:
            out[k] = (F.id[s] << 32) | F.id[v]
            k += 1
    return k
