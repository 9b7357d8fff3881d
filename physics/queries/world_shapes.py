"""The fixtures' world-space geometry for queries: vertices, edge normals, circle centres, tight boxes.

Queries must see where bodies are now (after the last step's position update and any edit),
while the store's world-space copies are those the step's collision stage saw.  This kernel
writes its own arrays, so a query never changes what the next step computes (the shipped
scenes' end states stay bit-identical).
"""
from __future__ import annotations

import math

from .._jit import kernel
from ..store.fixtures import CIRCLE


@kernel(entry=True)
def world_shapes(B, F, V, nf, wv, wn, wc, box):
    """Fill ``wv``/``wn`` (per pool vertex), ``wc`` and ``box`` (per fixture) for ``nf`` fixtures.

    ``box`` is the tight AABB of the rounded shape (core box grown by the radius), not the
    step's fattened one: the tree then culls exactly what cannot touch.
    """
    for f in range(nf):
        i = F.body[f]
        c = math.cos(B.q[i])
        s = math.sin(B.q[i])
        px = B.x[i, 0]
        py = B.x[i, 1]
        r = F.radius[f]
        if F.shape[f] == CIRCLE:
            wx = px + (c * F.center[f, 0] - s * F.center[f, 1])
            wy = py + (s * F.center[f, 0] + c * F.center[f, 1])
            wc[f, 0] = wx
            wc[f, 1] = wy
            box[f, 0] = wx - r
            box[f, 1] = wy - r
            box[f, 2] = wx + r
            box[f, 3] = wy + r
            continue
        lo_x = math.inf
        lo_y = math.inf
        hi_x = -math.inf
        hi_y = -math.inf
        for k in range(F.vstart[f], F.vstart[f] + F.vcount[f]):
            lx = V.local[k, 0]
            ly = V.local[k, 1]
            wx = px + c * lx - s * ly
            wy = py + s * lx + c * ly
            wv[k, 0] = wx
            wv[k, 1] = wy
            wn[k, 0] = c * V.normal[k, 0] - s * V.normal[k, 1]
            wn[k, 1] = s * V.normal[k, 0] + c * V.normal[k, 1]
            lo_x = min(lo_x, wx)
            lo_y = min(lo_y, wy)
            hi_x = max(hi_x, wx)
            hi_y = max(hi_y, wy)
        box[f, 0] = lo_x - r
        box[f, 1] = lo_y - r
        box[f, 2] = hi_x + r
        box[f, 3] = hi_y + r
