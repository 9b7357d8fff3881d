"""Scene-file shapes (version 1, and version 2 of issue 13) as Box2D v3 shape records.

Every shape spec of the format maps onto Box2D v3's own shape types:

* ``box`` -> ``b2MakeOffsetRoundedBox(w/2, h/2, 0, 0, radius)``; ``polygon`` / ``regular`` ->
  a ``b2Polygon`` built from the same vertices (counter-clockwise; no ``b2ComputeHull``, which
  welds points closer than 2 cm and would drop small polygons). ``"radius"`` rounds it
  outward, as Box2D's rounded polygons do (the listed vertices are the core).
* Box2D polygons have at most 8 vertices; a larger convex polygon becomes a fan of <= 8-vertex
  pieces on the same body (same area and mass, interior edges meet exactly).
* ``circle``, ``capsule``, ``segment`` map one to one. ``concave`` is split into convex pieces
  (``physics.decompose`` once it exists, else ear-clipped triangles).
* ``chain``: Box2D's chains need >= 4 points and give the first and last segment of an open
  chain no collision (they are only ghosts for smoothness). Stelkropp's open chain collides on
  every listed segment, so an open chain gets one collinear ghost point added at each end; a
  loop with fewer than 4 points gets its edges halved until it has 4.

Materials: Box2D has one friction coefficient per shape and mixes sqrt(mu_a mu_b) (its
``b2DefaultFrictionCallback``); restitution mixes by max (``b2DefaultRestitutionCallback``).
Stelkropp mixes each of its static and dynamic coefficients by the same geometric mean and
restitution by the same max, so the mixing matches; a ``{"static": s, "dynamic": d}`` pair
gives Box2D the dynamic coefficient (as bench/engines/ does for pybox2d and pymunk).
"""
from __future__ import annotations

import functools
import math

import numpy as np

from .lib import OP_SHAPE

KIND = {"circle": 0, "capsule": 1, "segment": 2, "polygon": 3, "box": 4, "chain": 5}
SHAPE_KEYS = ("box", "polygon", "regular", "circle", "capsule", "segment", "chain", "concave")
MAX_VERTS = 8
ALL_BITS = -1


def friction_of(value, path):
    """The Coulomb coefficient Box2D gets from a scene friction (number, pair or dict)."""
    if isinstance(value, dict):
        value = value.get("dynamic", value.get("static", 0.6))
    elif isinstance(value, (list, tuple)):
        value = value[1]
    value = float(value)
    if not value >= 0:
        raise ValueError(f"{path}: friction must be >= 0; got {value}")
    return value


def _bits(value, path, default):
    if value is None:
        return default
    v = int(value)
    if v < 0 or v != value:
        raise ValueError(f"{path}: must be a non-negative integer bit mask; got {value!r}")
    return v


def _split_bits(v):
    return (ALL_BITS, 0) if v == ALL_BITS else (v >> 32, v & 0xFFFFFFFF)


def material(spec, body, path):
    """Fixture material and filter: the shape object's own keys, else the body's."""
    def pick(key, default):
        return spec.get(key, body.get(key, default))
    ext = {**body.get("box2d", {}).get("shape", {}), **spec.get("box2d", {})}
    density = float(pick("density", 1.0))
    restitution = float(pick("restitution", 0.0))
    if not density > 0:
        raise ValueError(f"{path}.density: must be > 0; got {density}")
    if not 0 <= restitution:
        raise ValueError(f"{path}.restitution: must be >= 0; got {restitution}")
    flags = (1 if pick("sensor", False) else 0) | (2 if ext.get("hit_events") else 0) \
        | (4 if ext.get("sensor_events") else 0) | (8 if ext.get("contact_events") else 0)
    return dict(density=density, friction=friction_of(pick("friction", 0.6), f"{path}.friction"),
                restitution=restitution, rolling=float(ext.get("rolling_resistance", 0.0)),
                tangent=float(ext.get("tangent_speed", 0.0)),
                category=_bits(pick("category", None), f"{path}.category", 1),
                mask=_bits(pick("mask", None), f"{path}.mask", ALL_BITS),
                group=int(pick("group", 0)), flags=flags)


def _record(slot, kind, mat, radius, geom, extra_flags=0):
    ch, cl = _split_bits(mat["category"])
    mh, ml = _split_bits(mat["mask"])
    geom = [float(g) for g in geom]
    return [OP_SHAPE, slot, KIND[kind], mat["density"], mat["friction"], mat["restitution"], mat["rolling"],
            mat["tangent"], ch, cl, mh, ml, mat["group"], mat["flags"] | extra_flags, float(radius),
            len(geom), *geom]


def _points(value, path, least):
    try:
        p = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{path}: expected a list of [x, y] points") from None
    if p.ndim != 2 or p.shape[1] != 2 or len(p) < least:
        raise ValueError(f"{path}: expected at least {least} [x, y] points")
    if not np.isfinite(p).all():
        raise ValueError(f"{path}: points must be finite")
    return p


def convex_ccw(p, path):
    """Counter-clockwise convex polygon without repeated or collinear vertices; ValueError if not convex."""
    try:
        return np.array(_convex_ccw(tuple(map(tuple, np.asarray(p, float).tolist()))))
    except ValueError as e:
        raise ValueError(f"{path}: {e}") from None


@functools.lru_cache(maxsize=4096)
def _convex_ccw(pts):
    # plain Python: polygons have 3..64 points, and suites repeat the same few thousands of times
    n = len(pts)
    mx, my = sum(x for x, _ in pts) / n, sum(y for _, y in pts) / n
    scale = max(max(abs(x - mx), abs(y - my)) for x, y in pts) or 1.0
    keep = [q for i, q in enumerate(pts) if math.hypot(q[0] - pts[i - 1][0], q[1] - pts[i - 1][1]) > 1e-9 * scale]
    area = 0.5 * sum(keep[i - 1][0] * keep[i][1] - keep[i][0] * keep[i - 1][1] for i in range(len(keep)))
    if len(keep) < 3 or abs(area) <= 1e-12 * scale * scale:
        raise ValueError("polygon has zero area")
    if area < 0:
        keep = keep[::-1]
    tol = 1e-9 * scale * scale
    out = []
    for i, b in enumerate(keep):
        a, c = keep[i - 1], keep[(i + 1) % len(keep)]
        cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
        if cross < -tol:
            raise ValueError(f"polygon is not convex (reflex vertex at index {i})")
        if cross > tol:
            out.append(b)  # collinear vertices carry no edge of their own
    if len(out) < 3:
        raise ValueError("polygon has zero area")
    return tuple(out)


def fan(p):
    """Convex polygon -> list of convex pieces of <= MAX_VERTS vertices sharing vertex 0."""
    if len(p) <= MAX_VERTS:
        return [p]
    pieces, k = [], 1
    while k < len(p) - 1:
        end = min(k + MAX_VERTS - 2, len(p) - 1)
        pieces.append(np.vstack([p[:1], p[k:end + 1]]))
        k = end
    return pieces


def regular(sides, radius, path):
    """Vertices of a regular polygon with a flat bottom edge (physics.Polygon.regular's convention)."""
    n = int(sides)
    if n != sides or not 3 <= n <= 64 or not radius > 0:
        raise ValueError(f"{path}: regular polygon needs 3..64 sides and radius > 0")
    a0 = -0.5 * math.pi + math.pi / n
    return np.array([(radius * math.cos(a0 + 2 * math.pi * k / n), radius * math.sin(a0 + 2 * math.pi * k / n))
                     for k in range(n)])


def ear_clip(p):
    """Triangles of a simple polygon (counter-clockwise), by ear clipping: O(n^3), outlines are small."""
    idx = list(range(len(p)))
    tris = []

    def cross(u, v):
        return u[0] * v[1] - u[1] * v[0]

    def inside(a, b, c, q):
        return min(cross(b - a, q - a), cross(c - b, q - b), cross(a - c, q - c)) > 0
    while len(idx) > 3:
        for k in range(len(idx)):
            i0, i1, i2 = idx[k - 1], idx[k], idx[(k + 1) % len(idx)]
            a, b, c = p[i0], p[i1], p[i2]
            if cross(b - a, c - b) <= 0:
                continue
            if any(inside(a, b, c, p[j]) for j in idx if j not in (i0, i1, i2)):
                continue
            tris.append(np.array([a, b, c]))
            idx.pop(k)
            break
        else:
            raise ValueError("outline is self-intersecting or degenerate")
    tris.append(p[idx])
    return tris


def concave_pieces(p, path):
    """Convex pieces of a simple concave outline (``physics.decompose`` when it exists)."""
    try:
        import physics
        if hasattr(physics, "decompose"):
            return [np.asarray(q.vertices, float) for q in physics.decompose(p.tolist())]
    except ImportError:
        pass
    area = 0.5 * float(np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1]))
    q = p if area > 0 else p[::-1]
    try:
        return ear_clip(q)
    except ValueError as e:
        raise ValueError(f"{path}: {e}") from None


def _chain_points(spec, path):
    c = spec["chain"]
    pts = _points(c.get("points"), f"{path}.chain.points", 2)
    if c.get("loop", False):
        while len(pts) < 4:
            mids = 0.5 * (pts + np.roll(pts, -1, 0))
            pts = np.column_stack([pts, mids]).reshape(-1, 2)
        return pts, True
    d0, d1 = pts[0] - pts[1], pts[-1] - pts[-2]
    return np.vstack([pts[0] + d0, pts, pts[-1] + d1]), False


def shape_records(slot, spec, body, path):
    """Box2D shape records (lists of numbers) for one scene shape spec on body ``slot``."""
    if not isinstance(spec, dict):
        raise ValueError(f"{path}: a shape is an object with one of {', '.join(SHAPE_KEYS)}")
    kinds = [k for k in SHAPE_KEYS if k in spec]
    if len(kinds) != 1:
        raise ValueError(f"{path}: exactly one of {', '.join(SHAPE_KEYS)} expected; got {sorted(spec)}")
    kind = kinds[0]
    mat = material(spec, body, path)
    r = float(spec.get("radius", 0.0)) if kind in ("box", "polygon", "regular") else 0.0
    if r < 0:
        raise ValueError(f"{path}.radius: must be >= 0; got {r}")
    if kind == "box":
        w, h = map(float, spec["box"])
        if not (w > 0 and h > 0):
            raise ValueError(f"{path}.box: width and height must be > 0")
        return [_record(slot, "box", mat, r, [0.5 * w, 0.5 * h, 0.0, 0.0, 0.0])]
    if kind in ("polygon", "regular", "concave"):
        if kind == "polygon":
            pieces = fan(convex_ccw(_points(spec["polygon"], f"{path}.polygon", 3), f"{path}.polygon"))
        elif kind == "regular":
            g = spec["regular"]
            pieces = fan(regular(g.get("sides"), float(g.get("radius", 0)), f"{path}.regular"))
        else:
            outline = _points(spec["concave"], f"{path}.concave", 3)
            pieces = [q for piece in concave_pieces(outline, f"{path}.concave")
                      for q in fan(convex_ccw(np.asarray(piece, float), f"{path}.concave"))]
        return [_record(slot, "polygon", mat, r, q.ravel()) for q in pieces]
    if kind == "circle":
        c = spec["circle"]
        radius, off = (float(c["radius"]), c.get("offset", (0, 0))) if isinstance(c, dict) else (float(c), (0, 0))
        if not radius > 0:
            raise ValueError(f"{path}.circle: radius must be > 0")
        return [_record(slot, "circle", mat, radius, off)]
    if kind == "capsule":
        c = spec["capsule"]
        a, b, radius = c.get("a"), c.get("b"), float(c.get("radius", 0))
        if not radius > 0:
            raise ValueError(f"{path}.capsule.radius: must be > 0")
        return [_record(slot, "capsule", mat, radius, [*a, *b])]
    if kind == "segment":
        s = _points(spec["segment"], f"{path}.segment", 2)
        return [_record(slot, "segment", mat, 0.0, s[:2].ravel())]
    pts, loop = _chain_points(spec, path)
    return [_record(slot, "chain", mat, 0.0, pts.ravel(), 16 if loop else 0)]


def body_shapes(body, path):
    """The shape specs of a body: ``"shapes"`` (version 2) or the single ``"shape"`` (version 1)."""
    if "shapes" in body:
        shapes = body["shapes"]
        if not isinstance(shapes, list) or not shapes:
            raise ValueError(f"{path}.shapes: a non-empty list of shapes expected")
        return [(s, f"{path}.shapes[{i}]") for i, s in enumerate(shapes)]
    if "shape" in body:
        return [(body["shape"], f"{path}.shape")]
    raise ValueError(f"{path}: a body needs \"shape\" or \"shapes\"")


def has_area(spec):
    """Whether the shape spec has an area (segments and chains do not)."""
    return not ("segment" in spec or "chain" in spec)
