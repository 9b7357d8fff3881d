"""Polygon bodies as triangle fans for the poly shader, with the fan topology cached while the
polygons stay the same (one builder per set of layers: the main scene, each comparison lane)."""
from __future__ import annotations

import numpy as np

F32 = np.float32


class Fans:
    """``build(rd, fill, line)``: (centre, v_i, v_i+1) per polygon edge, 11 floats a vertex."""

    def __init__(self):
        self._key = None
        self._edge_body = self._ia = self._ib = None

    def topology(self, vstart, vcount):
        """(edge's body, first vertex index, second vertex index) of every polygon edge."""
        poly = np.nonzero(vcount >= 3)[0]
        key = (len(vcount), poly.tobytes(), vstart[poly].tobytes(), vcount[poly].tobytes())
        if key != self._key:
            counts = vcount[poly].astype(np.int64)
            edge_body = np.repeat(poly, counts)
            starts = np.repeat(np.cumsum(counts) - counts, counts)
            k = np.arange(counts.sum()) - starts
            cnt = np.repeat(counts, counts)
            base = np.repeat(vstart[poly].astype(np.int64), counts)
            self._edge_body, self._ia, self._ib = edge_body, base + k, base + (k + 1) % np.maximum(cnt, 1)
            self._key = key
        return self._edge_body, self._ia, self._ib

    def build(self, rd, fill, line, parts=None, part_colors=None):
        """Polygons as a fan of (centre, v_i, v_i+1) per edge; the centre vertex carries its
        distance to the edge so the shader can draw the outline.  ``fill``/``line``: (N, 4) per
        body.  ``parts`` (app.render.parts.Parts): draw each fixture by itself (a compound body's
        pieces, rounded outlines); without it, one polygon per body as in render data.
        ``part_colors``: (fill, line) per part of ``parts`` instead of per body (sensors)."""
        if parts is None:
            V, vstart, vcount, centre, owner = rd.vertices, rd.vstart, rd.vcount, rd.center, None
        else:
            V, vstart, vcount, centre, owner = parts.vertices, parts.vstart, parts.vcount, parts.centre, parts.body
        eb, ia, ib = self.topology(vstart, vcount)
        if not len(eb):
            return np.zeros((0, 11), F32)
        c, a, b = centre[eb], V[ia], V[ib]
        if part_colors is not None:
            fill, line = part_colors
        elif owner is not None:
            eb = owner[eb]
        e = b - a
        el = np.hypot(e[:, 0], e[:, 1])
        el[el == 0] = 1.0
        dist = np.abs(e[:, 0] * (c[:, 1] - a[:, 1]) - e[:, 1] * (c[:, 0] - a[:, 0])) / el
        pv = np.empty((len(eb), 3, 11), F32)
        pv[:, 0, 0:2] = c
        pv[:, 1, 0:2] = a
        pv[:, 2, 0:2] = b
        pv[:, 0, 2] = dist
        pv[:, 1:, 2] = 0.0
        pv[:, :, 3:7] = fill[eb][:, None, :]
        pv[:, :, 7:11] = line[eb][:, None, :]
        return pv.reshape(-1, 11)
