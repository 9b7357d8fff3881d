"""Which sensor pairs overlap: the exact shapes, not their boxes.

Each (sensor, visitor) pair of the broad phase runs the narrow phase's own shape dispatch
(kernel._manifold) with no margin: the shapes overlap when it finds a point of negative
separation.  Geometry is the step's (the start-of-step positions the contacts are found at).
"""
from __future__ import annotations

from ..._jit import kernel
from .kernel import _manifold, manifold_scratch


@kernel(entry=True, runtime=True)
def sensor_overlaps(ctx, B, F, V, spairs, ns, out):
    """Write the keys (sensor id << 32) | visitor id of the overlapping pairs of ``spairs[:ns]``
    to ``out``; returns their count (in pair order)."""
    sc_a, sc_b, sw, si, lam, poly, out_p, out_s, out_f = manifold_scratch()
    method = ctx[0].narrowphase
    k = 0
    for p in range(ns):
        s = spairs[p, 0]
        v = spairs[p, 1]
        # the orientation the contacts use (lower id first), so a pair is computed one way only
        fa, fb = (s, v) if F.id[s] < F.id[v] else (v, s)
        count, nx, ny = _manifold(B, F, V, fa, fb, F.body[fa], F.body[fb], method, 1, 0.0, sc_a, sc_b, sw, si,
                                  lam, poly, out_p, out_s, out_f)
        hit = False
        for q in range(count):
            hit = hit or out_s[q] < 0.0
        if hit:
            out[k] = (F.id[s] << 32) | F.id[v]
            k += 1
    return k
