"""Building blocks of the suite's scene descriptions (Stelkropp scene dicts, version 2 keys).

Conventions, so that one description runs in Stelkropp and in Box2D v3:

* ``box(hw, hh, ...)`` takes Box2D's half extents and writes the format's full ``{"box": [w, h]}``;
  Box2D's *rounded* boxes (``b2MakeRoundedBox(hx, hy, r)``) are ``{"box": [2hx, 2hy], "radius": r}``:
  the listed size is the core, the radius is added outside (outer size 2hx + 2r).
* An offset or rotated box (``b2MakeOffsetBox``) has no key of its own: it is a ``polygon`` of
  its four corners in body coordinates.
* Box2D's defaults are written out where they matter: density 1, friction 0.6, restitution 0.
* Box2D-only settings sit under ``"box2d"`` keys (ignored by Stelkropp; ``strip_box2d`` removes
  them); scripts (events, drives, step counts) under the top-level ``"bench"`` key.
"""
from __future__ import annotations

import copy
import math

FORMAT = "stelkropp.scene"


def scene(name, description, bodies, joints=(), gravity=(0.0, -10.0), sleeping=False, dt=1 / 60, substeps=4,
          steps=None, source=None, box2d=None, bench=None):
    """A version-2 scene dict; ``steps``/``source`` go under ``bench``, ``box2d`` under ``world``."""
    d = {"format": FORMAT, "version": 2, "name": name, "description": description,
         "world": {"gravity": [float(gravity[0]), float(gravity[1])], "dt": dt, "sleeping": bool(sleeping),
                   "settings": {"substeps": int(substeps)}},
         "bodies": list(bodies)}
    if joints:
        d["joints"] = list(joints)
    if box2d:
        d["world"]["box2d"] = dict(box2d)
    b = dict(bench or {})
    if steps is not None:
        b["steps"] = int(steps)
    if source is not None:
        b["source"] = source
    if b:
        d["bench"] = b
    return d


def body(shapes, x=0.0, y=0.0, kind="dynamic", angle=0.0, name=None, velocity=None, angular_velocity=0.0,
         box2d=None, **material):
    """A body dict: ``shapes`` is one shape dict or a list (written as ``"shapes"`` when several)."""
    b = {"kind": kind, "position": [float(x), float(y)]}
    if isinstance(shapes, dict):
        b["shape"] = shapes
    else:
        b["shapes"] = list(shapes)
    if angle:
        b["angle"] = float(angle)
    if velocity is not None and tuple(velocity) != (0.0, 0.0):
        b["velocity"] = [float(velocity[0]), float(velocity[1])]
    if angular_velocity:
        b["angular_velocity"] = float(angular_velocity)
    if name is not None:
        b["name"] = name
    for k, v in material.items():
        if v is not None:
            b[k] = v
    if box2d:
        b["box2d"] = dict(box2d)
    return b


def box(hw, hh, radius=0.0, **fixture):
    """Centred box from Box2D half extents (``b2MakeBox`` / ``b2MakeRoundedBox``)."""
    s = {"box": [2.0 * hw, 2.0 * hh]}
    if radius:
        s["radius"] = float(radius)
    s.update({k: v for k, v in fixture.items() if v is not None})
    return s


def offset_box(hw, hh, cx, cy, angle=0.0, **fixture):
    """``b2MakeOffsetBox``: a box centred at (cx, cy), turned by ``angle``, as a polygon."""
    c, s = math.cos(angle), math.sin(angle)
    pts = [(cx + c * x - s * y, cy + s * x + c * y) for x, y in ((-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh))]
    return polygon(pts, **fixture)


def polygon(points, radius=0.0, **fixture):
    """Convex polygon in body coordinates (counter-clockwise)."""
    s = {"polygon": [[float(x), float(y)] for x, y in points]}
    if radius:
        s["radius"] = float(radius)
    s.update({k: v for k, v in fixture.items() if v is not None})
    return s


def circle(radius, offset=(0.0, 0.0), **fixture):
    """Disc (``b2Circle``)."""
    s = {"circle": float(radius)} if tuple(offset) == (0.0, 0.0) else \
        {"circle": {"radius": float(radius), "offset": [float(offset[0]), float(offset[1])]}}
    s.update({k: v for k, v in fixture.items() if v is not None})
    return s


def capsule(a, b, radius, **fixture):
    """Capsule with end centres a, b (``b2Capsule``)."""
    s = {"capsule": {"a": [float(a[0]), float(a[1])], "b": [float(b[0]), float(b[1])], "radius": float(radius)}}
    s.update({k: v for k, v in fixture.items() if v is not None})
    return s


def segment(a, b, **fixture):
    """Two-sided segment (``b2Segment``), for static bodies."""
    s = {"segment": [[float(a[0]), float(a[1])], [float(b[0]), float(b[1])]]}
    s.update({k: v for k, v in fixture.items() if v is not None})
    return s


def chain(points, loop=False, **fixture):
    """Smooth one-sided chain (``b2ChainDef``), solid on the right of the point order."""
    s = {"chain": {"points": [[float(x), float(y)] for x, y in points], "loop": bool(loop)}}
    s.update({k: v for k, v in fixture.items() if v is not None})
    return s


def hull(points):
    """Counter-clockwise convex hull (Andrew's monotone chain), as ``b2ComputeHull`` orders a
    polygon's points (collinear points dropped)."""
    pts = sorted(set((float(x), float(y)) for x, y in points))

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def strip_box2d(desc):
    """A deep copy of ``desc`` without its Box2D-only ``"box2d"`` keys (world, bodies, shapes, joints)."""
    d = copy.deepcopy(desc)

    def clean(o):
        if isinstance(o, dict):
            o.pop("box2d", None)
            for v in o.values():
                clean(v)
        elif isinstance(o, list):
            for v in o:
                clean(v)
    clean(d)
    return d


def counts(desc):
    """(bodies, shapes, joints) of a description, events included."""
    def shapes_of(b):
        return len(b.get("shapes", [])) or 1
    bodies = list(desc.get("bodies", []))
    joints = list(desc.get("joints", []))
    for e in desc.get("bench", {}).get("events", []):
        bodies += e.get("add", {}).get("bodies", [])
        joints += e.get("add", {}).get("joints", [])
    return len(bodies), sum(shapes_of(b) for b in bodies), len(joints)
