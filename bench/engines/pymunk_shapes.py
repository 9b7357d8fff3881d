"""Fixtures of every shape kind as pymunk shapes, for bodies made of several shapes (issue 13).

Chipmunk has polygons with a radius, circles with an offset and segments with a radius, so each
Stelkropp shape maps to one pymunk shape without approximation: a rounded polygon to
``Poly(radius=r)``, a capsule to ``Segment(a, b, r)`` (its moment set exactly, see ``add_parts``), a segment to ``Segment(a, b, 0)``, and a
chain segment to a segment whose ``set_neighbors`` are the chain's ghost vertices (Chipmunk's
own way of keeping sliding bodies from catching on the joins).  Material is compensated as in
``pymunk_sim``: friction sqrt(mu) per shape (Chipmunk multiplies), restitution as given.
"""
from __future__ import annotations

import math


def pymunk_shape(pymunk, body, shape):
    """The pymunk shape on ``body`` for one Stelkropp shape (body coordinates)."""
    kind = type(shape).__name__
    if kind == "Circle":
        return pymunk.Circle(body, float(shape.radius), tuple(map(float, shape.offset)))
    if kind == "Polygon":
        return pymunk.Poly(body, [tuple(map(float, v)) for v in shape.vertices], radius=float(shape.radius))
    if kind == "Capsule":
        return pymunk.Segment(body, tuple(map(float, shape.a)), tuple(map(float, shape.b)), float(shape.radius))
    if kind in ("Segment", "ChainSegment"):
        a, b = (tuple(map(float, v)) for v in shape.vertices)
        seg = pymunk.Segment(body, a, b, 0.0)
        if kind == "ChainSegment":
            seg.set_neighbors(*(tuple(map(float, g)) for g in shape.ghost))
        return seg
    raise ValueError(f"pymunk adapter: no pymunk shape for {kind}")


def add_parts(pymunk, space, body, rec, any_e):
    """Add every fixture of body record ``rec`` (``rec["parts"]``) to ``body`` and ``space``."""
    dynamic = rec["kind"] == "dynamic"
    for shape, f in rec["parts"]:
        s = pymunk_shape(pymunk, body, shape)
        if dynamic and shape.area > 0.0:
            s.density = f["density"]
        s.friction = math.sqrt(f["mu_d"])
        e = f["restitution"]
        s.elasticity = 1.0 if (not dynamic and e == 0.0 and any_e) else e
        space.add(s)
    if dynamic:
        # Chipmunk's moment of a radius segment treats the capsule as a (L + 2r) x 2r rectangle
        # (cpMomentForSegment); ours is exact (a rectangle and two half discs).  The same body in
        # both engines needs the same inertia, so the exact sum is set (about the centre of mass,
        # as Chipmunk's moment is); mass and centre already agree.
        body.moment = float(rec["shape"].mass_properties()[2])
