"""Bodies as plain specs that keep every fixture (issue 13): undo, copy, reset, glue and unglue
rebuild a compound body with each fixture's shape, material and filter bits.

A body spec is ``{"shape": first shape, "fixtures": [fixture spec, ...] (optional), kind,
position, ...}``; a fixture spec is ``{"shape": ..., density, friction, restitution, category,
mask, group, name}``.  The shapes of one chain (its segments) travel as the Chain itself.
"""
from __future__ import annotations

import numpy as np

import physics
from physics.geometry.chain import ChainSegment

BODY_FIELDS = ("kind", "position", "angle", "velocity", "angular_velocity", "density", "restitution",
               "friction", "name")
FIXTURE_FIELDS = ("density", "friction", "restitution", "category", "mask", "group", "name")


def fixture_specs(body) -> list[dict]:
    """The body's fixtures as specs; consecutive segments of one chain become one Chain spec."""
    out = []
    for f in body.fixtures:
        shape = f.shape
        if isinstance(shape, ChainSegment):
            if out and out[-1]["shape"] is shape.chain:
                continue
            shape = shape.chain
        out.append({"shape": shape, **{k: getattr(f, k) for k in FIXTURE_FIELDS}})
    return out


def body_spec(b) -> dict:
    return {"shape": b.shape, "fixtures": fixture_specs(b), **{f: getattr(b, f) for f in BODY_FIELDS}}


def make_body(world, spec: dict):
    """``world.add_body`` for a spec; each fixture gets its own material and filter back."""
    fx = spec.get("fixtures")
    if not fx:
        return world.add_body(spec["shape"], **{f: spec[f] for f in BODY_FIELDS})
    b = world.add_body([s["shape"] for s in fx], **{f: spec[f] for f in BODY_FIELDS})
    made = b.fixtures
    k = 0
    for s in fx:
        count = len(s["shape"].segments) if isinstance(s["shape"], physics.Chain) else 1
        for f in made[k:k + count]:
            for name in FIXTURE_FIELDS:
                if getattr(f, name) != s[name]:
                    setattr(f, name, s[name])
        k += count
    return b


def moved_shape(shape, rot: np.ndarray, off: np.ndarray):
    """``shape`` with every point p taken to rot @ p + off (a rigid placement change)."""
    def tr(p):
        return np.asarray(p, dtype=np.float64) @ rot.T + off
    if isinstance(shape, physics.Circle):
        return physics.Circle(shape.radius, offset=tuple(tr(shape.offset)))
    if isinstance(shape, physics.Capsule):
        return physics.Capsule(tr(shape.a), tr(shape.b), shape.radius)
    if isinstance(shape, physics.Segment):
        a, b = tr(shape.vertices)
        return physics.Segment(a, b)
    if isinstance(shape, physics.Chain):
        return physics.Chain(tr(shape.points), loop=shape.loop)
    return physics.Polygon(tr(shape.vertices), radius=shape.radius)


def _rot(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s], [s, c]])


def glued_spec(bodies) -> dict:
    """One body holding every fixture of ``bodies`` where it is in the world, in the first body's
    frame.  Velocity: the bodies' total linear momentum over their total mass; kind: static if
    one is static, else kinematic if one is, else dynamic."""
    first = bodies[0]
    r0 = _rot(first.angle)
    p0 = np.asarray(first.position)
    fixtures = []
    for b in bodies:
        # body b's local p -> world R_b p + x_b -> first's local R0^T (world - x0)
        rot = r0.T @ _rot(b.angle)
        off = r0.T @ (np.asarray(b.position) - p0)
        for s in fixture_specs(b):
            fixtures.append(dict(s, shape=moved_shape(s["shape"], rot, off)))
    kinds = {b.kind for b in bodies}
    kind = "static" if "static" in kinds else "kinematic" if "kinematic" in kinds else "dynamic"
    m = np.array([b.mass if b.kind == "dynamic" else 0.0 for b in bodies])
    v = np.array([b.velocity for b in bodies])
    vel = tuple(m @ v / m.sum()) if kind == "dynamic" and m.sum() > 0 else (0.0, 0.0)
    spec = {f: getattr(first, f) for f in BODY_FIELDS}
    spec.update(kind=kind, velocity=tuple(map(float, vel)), angular_velocity=0.0 if kind == "static" else
                float(first.angular_velocity), shape=fixtures[0]["shape"], fixtures=fixtures)
    return spec


def unglued_specs(body) -> list[dict]:
    """One body spec per fixture (a chain stays one body), each in the body's own frame and
    moving as that part of the body moved: v + w x (c_part - c_body)."""
    base = {f: getattr(body, f) for f in BODY_FIELDS}
    w = float(body.angular_velocity)
    v = np.asarray(body.velocity)
    com = np.asarray(body.center_of_mass)
    rot, x = _rot(body.angle), np.asarray(body.position)
    out = []
    for k, s in enumerate(fixture_specs(body)):
        c = rot @ _part_centroid(s["shape"]) + x
        r = c - com
        vel = v + w * np.array([-r[1], r[0]])
        out.append(dict(base, shape=s["shape"], fixtures=[s], name=base["name"] if k == 0 else None,
                        velocity=tuple(map(float, vel)), density=s["density"], friction=s["friction"],
                        restitution=s["restitution"]))
    return out


def _part_centroid(shape) -> np.ndarray:
    if isinstance(shape, physics.Circle):
        return np.asarray(shape.offset)
    pts = shape.points if isinstance(shape, physics.Chain) else shape.vertices
    return np.asarray(pts).mean(axis=0)
