"""Springs and joints moved onto the bodies that replace the ones they held (glue, unglue: issue 13).

A replaced body's place inside its replacement is a :class:`Place`: the new body's Ref and the
rigid map from the old body's coordinates to the new one's (``p -> rot @ p + off``, the old body's
angle minus the new one's ``turn``).  Each end of a spring or joint keeps its world anchor: its
body-frame anchor goes through that map, and whatever is measured between the two bodies (a
joint's reference angle, axis, a motor's offsets) is corrected by the same map, so the joint
starts out exactly as satisfied as before.  An end whose body is not replaced stays as it is.

``place(ref, p)`` answers for one end: the Place of the body held by ``ref`` for an anchor at
``p`` (its body coordinates), or None when that body is not replaced.  Unglue uses ``p`` to pick
the part the anchor lies in (:func:`nearest_part`); glue ignores it.
"""
from __future__ import annotations

from collections import namedtuple

import numpy as np

import physics

Place = namedtuple("Place", "ref rot off turn")
ORIGIN = (0.0, 0.0)


def rot(angle) -> np.ndarray:
    """The 2x2 rotation by ``angle`` (rad)."""
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s], [s, c]])


def part_place(ref, first, body) -> Place:
    """Where ``body`` sits in the glued body made in ``first``'s frame (app.fixture_specs.glued_spec):
    first's local R0^T (R_b p + x_b - x0)."""
    r0 = rot(first.angle)
    return Place(ref, r0.T @ rot(body.angle), r0.T @ (np.asarray(body.position) - np.asarray(first.position)),
                 float(body.angle - first.angle))


def _map(place: Place, p):
    return tuple(map(float, place.rot @ np.asarray(p, dtype=np.float64) + place.off))


def moved_spring(spec: dict, place):
    """``spec`` (app.commands.spring_spec) with each replaced end moved onto its replacement, or
    None when both ends land on one body (a spring needs two)."""
    pa = place(spec["a"], spec["anchor_a"])
    pb = None if spec["b"] is None else place(spec["b"], spec["anchor_b"])
    out = dict(spec)
    if pa is not None:
        out.update(a=pa.ref, anchor_a=_map(pa, spec["anchor_a"]))
    if pb is not None:
        out.update(b=pb.ref, anchor_b=_map(pb, spec["anchor_b"]))
    return None if out["a"] is out["b"] else out


def moved_joint(spec: dict, place):
    """``spec`` (app.commands.joint_spec) with each replaced end moved onto its replacement, or
    None when both ends land on one body (the joint would hold nothing: it is dropped)."""
    f = spec["fields"]
    pa = place(spec["a"], f.get("local_anchor_a", ORIGIN))
    pb = None if spec["b"] is None else place(spec["b"], f.get("local_anchor_b", ORIGIN))
    if pa is None and pb is None:
        return spec
    a = pa.ref if pa is not None else spec["a"]
    b = pb.ref if pb is not None else spec["b"]
    if a is b:
        return None
    return dict(spec, a=a, b=b, fields=_moved_fields(spec["kind"], dict(f), pa, pb))


def _moved_fields(kind, f, pa, pb):
    # the relative angle a - b reads (a_old - turn_a) - (b_old - turn_b) on the new bodies
    da = 0.0 if pa is None else pa.turn
    db = 0.0 if pb is None else pb.turn
    if pa is not None and "local_anchor_a" in f:
        f["local_anchor_a"] = _map(pa, f["local_anchor_a"])
    if pb is not None and "local_anchor_b" in f:
        f["local_anchor_b"] = _map(pb, f["local_anchor_b"])
    if pa is not None and "local_axis" in f:
        f["local_axis"] = tuple(map(float, pa.rot @ np.asarray(f["local_axis"])))
    if "reference_angle" in f:
        f["reference_angle"] = float(f["reference_angle"] - da + db)
    if kind == "motor":
        _moved_motor(f, pa, pb, da, db)
    return f


def _moved_motor(f, pa, pb, da, db):
    """A motor pulls a's origin to ``linear_offset`` in b's frame at ``angular_offset`` from b.
    The old target of a's origin, in the new b's frame, is map_b(offset); the new a's origin sits
    ``off_a`` behind a's old origin, turned by the target angle: offset' = map_b(offset) - R(ang') off_a."""
    ang = float(f["angular_offset"] - da + db)
    lin = np.asarray(f["linear_offset"], dtype=np.float64)
    if pb is not None:
        lin = pb.rot @ lin + pb.off
    if pa is not None:
        lin = lin - rot(ang) @ pa.off
    f["angular_offset"], f["linear_offset"] = ang, tuple(map(float, lin))


def nearest_part(shapes, p) -> int:
    """Index of the shape (all in one body's coordinates) that point ``p`` lies deepest in, or
    the nearest one when it lies in none."""
    p = np.asarray(p, dtype=np.float64)
    return int(np.argmin([shape_distance(s, p) for s in shapes]))


def shape_distance(shape, p) -> float:
    """Distance from ``p`` to ``shape`` (body coordinates); <= 0 inside, the depth below zero."""
    if isinstance(shape, physics.Circle):
        return float(np.hypot(*(p - np.asarray(shape.offset)))) - shape.radius
    if isinstance(shape, physics.Capsule):
        return _segment_distance(p, np.asarray(shape.a), np.asarray(shape.b)) - shape.radius
    if isinstance(shape, physics.Chain):
        pts = np.asarray(shape.points, dtype=np.float64)
        ends = np.vstack([pts[1:], pts[:1]]) if shape.loop else pts[1:]
        return min(_segment_distance(p, a, b) for a, b in zip(pts, ends))
    v = np.asarray(shape.vertices, dtype=np.float64)
    if len(v) == 2:                       # a segment
        return _segment_distance(p, v[0], v[1])
    edge = min(_segment_distance(p, a, b) for a, b in zip(v, np.roll(v, -1, axis=0)))
    return (-edge if _inside_convex(v, p) else edge) - shape.radius


def _segment_distance(p, a, b) -> float:
    d = b - a
    t = 0.0 if not d.any() else float(np.clip((p - a) @ d / (d @ d), 0.0, 1.0))
    return float(np.hypot(*(p - a - t * d)))


def _inside_convex(v, p) -> bool:
    e = np.roll(v, -1, axis=0) - v
    r = p - v
    cross = e[:, 0] * r[:, 1] - e[:, 1] * r[:, 0]
    return bool((cross >= 0).all() or (cross <= 0).all())
