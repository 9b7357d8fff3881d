"""Box2D v3's sample descriptions (bench/suite) as Stelkropp builds them today.

The suite's descriptions use Box2D's shape kinds.  Where the installed ``physics`` cannot build a
shape (``bench.desc.shape_of`` refuses it), ``ours_desc`` substitutes the nearest shape it can,
and says so in ``notes``; every substitution keeps the surface the other bodies touch:

* a static **segment** -> a static box 1 m thick whose face lies on the segment, on the side away
  from the dynamic bodies (a two-sided segment has no thickness; nothing in the samples reaches
  its far side);
* a **rounded** box (``"radius": r``) -> the sharp box of its outer size (core + 2 r): same
  footprint and height, square corners;
* a **capsule** -> the convex hull of its two end discs sampled at 8 points each (a 16-gon
  inside the capsule, touching it at the sample points);
* a static body with several **shapes** -> one static body per shape, appended after the
  description's bodies so that every original body keeps its index.
"""
from __future__ import annotations

import copy
import math

import numpy as np

from ..desc import shape_of

SEGMENT_THICKNESS = 1.0  # m: the box that stands in for a static segment
CAPSULE_SAMPLES = 8      # points per end disc of a capsule's polygon


def _buildable(spec) -> bool:
    try:
        shape_of(spec)
    except (ValueError, KeyError, TypeError):
        return False
    return "radius" not in spec or _takes_radius()


def _takes_radius() -> bool:
    """Whether physics.Polygon takes a rounding radius (the shapes work adds it)."""
    import inspect

    import physics
    return "radius" in inspect.signature(physics.Polygon.__init__).parameters


def _material(spec):
    return {k: spec[k] for k in ("friction", "restitution", "density") if k in spec}


def _segment_box(a, b, away_from):
    a, b = np.asarray(a, float), np.asarray(b, float)
    d = b - a
    n = np.array([-d[1], d[0]]) / np.hypot(*d)
    mid = 0.5 * (a + b)
    if np.dot(np.asarray(away_from) - mid, n) > 0:
        n = -n  # the box goes on the side away from the bodies
    far = n * SEGMENT_THICKNESS
    return [a.tolist(), b.tolist(), (b + far).tolist(), (a + far).tolist()]


def _ccw(pts):
    p = np.asarray(pts, float)
    x, y = p[:, 0], p[:, 1]
    area = 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))
    return (p if area > 0 else p[::-1]).tolist()


def _capsule_polygon(c):
    a, b, r = np.asarray(c["a"], float), np.asarray(c["b"], float), float(c["radius"])
    axis = math.atan2(*(b - a)[::-1])
    pts = []
    for centre, start in ((b, axis - 0.5 * math.pi), (a, axis + 0.5 * math.pi)):
        for k in range(CAPSULE_SAMPLES):
            t = start + math.pi * k / (CAPSULE_SAMPLES - 1)
            pts.append((centre + r * np.array([math.cos(t), math.sin(t)])).tolist())
    return pts


def _substitute(spec, away_from, notes):
    """A buildable stand-in for ``spec`` (a shape dict), or ``spec`` itself when buildable."""
    if _buildable(spec):
        return spec
    mat = _material(spec)
    if "segment" in spec:
        notes.add("segments as 1 m thick static boxes")
        return {"polygon": _ccw(_segment_box(*spec["segment"], away_from)), **mat}
    if "capsule" in spec:
        notes.add(f"capsules as {2 * CAPSULE_SAMPLES}-gons")
        return {"polygon": _ccw(_capsule_polygon(spec["capsule"])), **mat}
    if "box" in spec and "radius" in spec:
        notes.add("rounded boxes as sharp boxes of their outer size")
        r = float(spec["radius"])
        w, h = spec["box"]
        return {"box": [w + 2 * r, h + 2 * r], **mat}
    raise ValueError(f"no stand-in for shape {spec!r}")


def _place(body, spec):
    b = {k: v for k, v in body.items() if k not in ("shape", "shapes")}
    b["shape"] = spec
    for k, v in _material(spec).items():
        b.setdefault(k, v)
    return b


def ours_desc(desc):
    """(description Stelkropp can build, sorted list of substitutions made); see the module doc."""
    d = copy.deepcopy(desc)
    dyn = [b["position"] for b in d["bodies"] if b.get("kind", "dynamic") == "dynamic"]
    centre = np.mean(dyn, axis=0) if dyn else np.zeros(2)
    notes, extra, bodies = set(), [], []
    for b in d["bodies"]:
        shapes = b.get("shapes") or [b["shape"]]
        local_centre = np.asarray(centre) - np.asarray(b.get("position", (0.0, 0.0)))
        subs = [_substitute(s, local_centre, notes) for s in shapes]
        if len(subs) > 1 and b.get("kind", "dynamic") == "dynamic":
            raise ValueError(f"body {b.get('name')!r}: several shapes on a dynamic body")
        if len(subs) > 1:
            notes.add("a static body's shapes as separate static bodies")
        bodies.append(_place(b, subs[0]))
        for s in subs[1:]:
            extra.append({k: v for k, v in _place(b, s).items() if k != "name"})
    d["bodies"] = bodies + extra
    return d, sorted(notes)
