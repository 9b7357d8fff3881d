"""Random worlds of every fixture shape for the query tests (hypothesis strategies)."""
from __future__ import annotations

from hypothesis import strategies as st

import physics

coord = st.floats(-8, 8, allow_nan=False)
size = st.floats(0.2, 3.0)


@st.composite
def shapes(draw):
    """One shape of every kind the fixture table has (and whether it must be static)."""
    kind = draw(st.sampled_from(["box", "regular", "rounded", "circle", "capsule", "segment", "chain"]))
    if kind == "box":
        return physics.Polygon.box(draw(size), draw(size)), False
    if kind == "regular":
        return physics.Polygon.regular(draw(st.integers(3, 9)), draw(size)), False
    if kind == "rounded":
        return physics.Polygon.box(draw(size), draw(size), radius=draw(st.floats(0.05, 0.8))), False
    if kind == "circle":
        return physics.Circle(draw(size), offset=(draw(st.floats(-1, 1)), draw(st.floats(-1, 1)))), False
    if kind == "capsule":
        return physics.Capsule((-draw(size), 0.0), (draw(size), 0.3), draw(st.floats(0.1, 1.0))), False
    if kind == "segment":
        return physics.Segment((-draw(size), 0.0), (draw(size), draw(st.floats(-1, 1)))), True
    xs = sorted(draw(st.lists(st.integers(-8, 8), min_size=3, max_size=5, unique=True)))
    pts = [(0.5 * x, draw(st.floats(-1, 1))) for x in xs]  # >= 0.5 m apart: a valid chain
    return physics.Chain(pts), True


@st.composite
def worlds(draw, max_bodies=14):
    """A world of 1..max_bodies bodies (a few multi-fixture), stepped 0-3 times so queries must
    see positions after a step, with random filter categories."""
    w = physics.World(gravity=(0, -9.81))
    for _ in range(draw(st.integers(1, max_bodies))):
        shape, static = draw(shapes())
        extra = [] if static or not draw(st.booleans()) else [draw(shapes())[0]]
        extra = [s for s in extra if not isinstance(s, (physics.Segment, physics.Chain))]
        b = w.add_body([shape] + extra if extra else shape, kind="static" if static else "dynamic",
                       position=(draw(coord), draw(coord)), angle=draw(st.floats(-3.2, 3.2)),
                       angular_velocity=draw(st.floats(-3, 3)))
        for f in b.fixtures:
            f.category = draw(st.sampled_from([1, 1, 2, 4]))
    for _ in range(draw(st.integers(0, 3))):
        w.step()
    return w


def all_fixtures(w):
    return [f for b in w.bodies for f in b.fixtures]
