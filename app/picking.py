"""What lies under the pointer: every body at a point (topmost first), and the joint nearest to it.

``World.query_point`` answers only the topmost body; the joint tools need the two topmost (a hinge
joins them), so ``bodies_at`` tests every body's drawn shape from the render data (the same
vertices the renderer fills: what is seen is what is picked).
"""
from __future__ import annotations

import numpy as np

from .render.joints import joint_segments

#: a joint's pin, weld mark or hub is picked within this many pixels, its lines within LINE_PX
PIN_PX = 8.0
LINE_PX = 6.0


def bodies_at(world, p, rd=None) -> list:
    """Every body whose shape contains world point ``p``, topmost (last added) first."""
    rd = world.render_data() if rd is None else rd
    p = np.asarray(p, dtype=np.float64)
    box = rd.aabb
    cand = np.nonzero((box[:, 0] <= p[0]) & (p[0] <= box[:, 2]) & (box[:, 1] <= p[1]) & (p[1] <= box[:, 3]))[0]
    handles = {b.id: b for b in world.bodies}
    out = []
    for s in cand[::-1]:
        k = int(rd.vcount[s])
        if k == 0:
            inside = np.hypot(*(p - rd.center[s])) <= rd.radius[s]
        else:
            v = rd.vertices[int(rd.vstart[s]):int(rd.vstart[s]) + k]
            e = np.roll(v, -1, axis=0) - v
            # counter-clockwise convex polygon: p is left of (or on) every edge
            inside = np.all(e[:, 0] * (p[1] - v[:, 1]) - e[:, 1] * (p[0] - v[:, 0]) >= 0)
        if inside:
            out.append(handles[int(rd.ids[s])])
    return out


def _segment_distance(p, a, b):
    d = b - a
    t = np.clip(np.einsum("ij,ij->i", p - a, d) / np.maximum(np.einsum("ij,ij->i", d, d), 1e-12), 0, 1)
    return np.hypot(*(a + t[:, None] * d - p).T)


def joint_near(world, p, scale, skip=(), lines=True):
    """The joint whose pin (anchor) lies within PIN_PX screen pixels of ``p`` or, with ``lines``,
    whose drawn lines pass within LINE_PX; the nearest one, or None.  ``skip``: joint ids to
    ignore (the mouse drag's)."""
    rows = world.render_data().joints
    if rows is None or not len(rows):
        return None
    keep = ~np.isin(rows["id"], np.fromiter(skip, np.int64, len(skip)) if skip else np.zeros(0, np.int64))
    rows = rows[keep]
    if not len(rows):
        return None
    p = np.asarray(p, dtype=np.float64)
    pins = np.minimum(np.hypot(*(rows["anchor_a"] - p).T), np.hypot(*(rows["anchor_b"] - p).T)) * scale
    best = int(np.argmin(pins))
    by_id = {j.id: j for j in world.joints}
    if pins[best] <= PIN_PX:
        return by_id.get(int(rows["id"][best]))
    if not lines:
        return None
    row, a, b = joint_segments(rows, scale)
    if not len(row):
        return None
    dist = _segment_distance(p, a, b) * scale
    k = int(np.argmin(dist))
    return by_id.get(int(rows["id"][row[k]])) if dist[k] <= LINE_PX else None
