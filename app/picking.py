"""What lies under the pointer: every body at a point (topmost first), and the joint nearest to it.

Every tool picks bodies through ``bodies_at`` (``body_at``: the topmost), so select, spring and
the joint tools agree: it tests every fixture of every body (each piece of a compound or of a
decomposed concave outline, capsules and rounded polygons out to their radius, either winding)
from the render data, the vertices the renderer fills: what is seen is what is picked.
"""
from __future__ import annotations

import numpy as np

from physics.store.fixtures import CIRCLE

from .render.joints import joint_segments

#: a joint's pin, weld mark or hub is picked within this many pixels, its lines within LINE_PX
PIN_PX = 8.0
LINE_PX = 6.0


def _inside_piece(p, v, r) -> bool:
    """Is ``p`` inside the convex piece with vertices ``v`` (either winding; 1 or 2 vertices:
    a point or a segment) grown by radius ``r``?"""
    k = len(v)
    if k >= 3:
        e = np.roll(v, -1, axis=0) - v
        cross = e[:, 0] * (p[1] - v[:, 1]) - e[:, 1] * (p[0] - v[:, 0])
        if np.all(cross >= 0) or np.all(cross <= 0):
            return True
    if r <= 0.0:
        return False
    a, b = (v, np.roll(v, -1, axis=0)) if k > 1 else (v, v)
    return bool(np.min(_segment_distance(p, a, b)) <= r)


def bodies_at(world, p, rd=None) -> list:
    """Every body one of whose fixtures contains world point ``p``, topmost (last added) first."""
    rd = world.render_data() if rd is None else rd
    p = np.asarray(p, dtype=np.float64)
    box = rd.aabb
    slots = set(np.nonzero((box[:, 0] <= p[0]) & (p[0] <= box[:, 2]) & (box[:, 1] <= p[1]) & (p[1] <= box[:, 3]))[0])
    if not slots:
        return []
    fx = rd.fixtures
    hit = set()
    for f in np.nonzero(np.isin(fx["body"], list(slots)))[0]:
        s, r = int(fx["body"][f]), float(fx["radius"][f])
        if s in hit:
            continue
        if fx["shape"][f] == CIRCLE:
            inside = np.hypot(*(p - fx["center"][f])) <= r
        else:
            a = int(fx["vstart"][f])
            inside = _inside_piece(p, rd.vertices[a:a + int(fx["vcount"][f])], r)
        if inside:
            hit.add(s)
    handles = {b.id: b for b in world.bodies}
    return [handles[int(rd.ids[s])] for s in sorted(hit, reverse=True)]


def body_at(world, p, rd=None):
    """The topmost body at world point ``p``, or None."""
    under = bodies_at(world, p, rd)
    return under[0] if under else None


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
