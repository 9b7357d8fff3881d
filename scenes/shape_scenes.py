"""The scenes of bodies made of many shapes (issue 13), built with make_scenes.py's helpers.

``scenes(h)`` returns {name: maker}; ``h`` carries make_scenes' helpers (scene, body, static,
box, r, ground), passed in so this module needs no import of a script.
"""
from __future__ import annotations

import math
import random


def tumbler(h):
    """Box2D's tumbler benchmark (shared/benchmarks.c, CreateTumbler) at a size Python steps: a
    hollow square drum of four box fixtures on one kinematic body turning at a set speed."""
    half, wall, omega = 5.0, 0.5, 0.5
    drum = [{"polygon": _offset_box(half + wall, 0.5 * wall, 0.0, -half - 0.5 * wall, h.r)},
            {"polygon": _offset_box(half + wall, 0.5 * wall, 0.0, half + 0.5 * wall, h.r)},
            {"polygon": _offset_box(0.5 * wall, half, -half - 0.5 * wall, 0.0, h.r)},
            {"polygon": _offset_box(0.5 * wall, half, half + 0.5 * wall, 0.0, h.r)}]
    bodies = [{"name": "drum", "kind": "kinematic", "shapes": drum, "position": [0.0, 8.0],
               "angular_velocity": omega}]
    rng = random.Random(500)
    spacing = 0.5
    slots = [(-half + 0.35 + i * spacing, 8.0 - half + 0.35 + j * spacing) for j in range(19) for i in range(19)]
    rng.shuffle(slots)
    for k, (x, y) in enumerate(sorted(slots[:300], key=lambda p: (p[1], p[0]))):
        kind = k % 3
        shape = ({"box": [0.35, 0.35]} if kind == 0 else {"circle": 0.19} if kind == 1
                 else {"capsule": {"a": [-0.12, 0.0], "b": [0.12, 0.0], "radius": 0.1}})
        bodies.append(h.body(shape, x, y, None, friction=0.5))
    return h.scene("Tumbler", "300 boxes, discs and capsules tumbling in a drum: one kinematic body made of four "
                              "box fixtures (a hollow square) turning at 0.5 rad/s about its centre, as in Box2D's "
                              "tumbler benchmark.",
                   bodies, camera={"center": [0.0, 8.0], "zoom": 40.0})


def _offset_box(hw, hh, cx, cy, r):
    return [[r(cx - hw), r(cy - hh)], [r(cx + hw), r(cy - hh)], [r(cx + hw), r(cy + hh)], [r(cx - hw), r(cy + hh)]]


def cup(h):
    """A concave cup (one outline, decomposed on load) holding ten balls."""
    outline = [[-1.5, 0.0], [1.5, 0.0], [1.8, 2.0], [1.6, 2.0], [1.3, 0.2], [-1.3, 0.2], [-1.6, 2.0], [-1.8, 2.0]]
    bodies = [h.ground(20.0), {"name": "cup", "shape": {"concave": outline}, "position": [0.0, 0.0], "density": 5.0}]
    for k in range(10):
        bodies.append(h.body({"circle": 0.2}, -1.0 + 0.5 * (k % 5), 0.6 + 0.5 * (k // 5), f"ball{k}",
                             restitution=0.2))
    return h.scene("Cup", "A concave cup (drawn as one outline, split into convex pieces on load) holding ten "
                          "balls on the ground.  Try dragging the cup by its rim: the balls ride "
                          "inside the one body.", bodies, camera={"center": [0.0, 1.5], "zoom": 120.0})


def capsules(h):
    """A pile of capsules dropped into a box."""
    bodies = [h.ground(12.0), h.static(h.box(0.5, 6.0), -4.25, 3.0, "wall_left"),
              h.static(h.box(0.5, 6.0), 4.25, 3.0, "wall_right")]
    rng = random.Random(13)
    for k in range(60):
        x = -3.0 + 1.2 * (k % 6)
        y = 0.6 + 0.6 * (k // 6)
        bodies.append(h.body({"capsule": {"a": [-0.35, 0.0], "b": [0.35, 0.0], "radius": 0.2}}, x, y, None,
                             angle=h.r(rng.uniform(-0.4, 0.4)), friction=0.6))
    return h.scene("Capsule pile", "Sixty capsules (two-vertex rounded shapes) dropped between two walls.",
                   bodies, camera={"center": [0.0, 3.5], "zoom": 70.0})


def terrain(h):
    """Rolling terrain as one static chain, with boxes sliding and balls rolling over it."""
    pts = [[h.r(30.0 - 0.5 * k), h.r(1.2 * math.sin(0.25 * (30.0 - 0.5 * k)) + 0.4 * math.sin(0.9 * (30.0 - 0.5 * k)))]
           for k in range(121)]  # x from 30 down to -30: right to left, solid below
    bodies = [{"name": "terrain", "kind": "static", "shape": {"chain": {"points": pts}}, "position": [0.0, 0.0],
               "friction": 0.4}]
    for k in range(8):
        x = -26.0 + 7.0 * k
        y = 1.2 * math.sin(0.25 * x) + 0.4 * math.sin(0.9 * x) + 2.5
        shape = {"box": [0.8, 0.8]} if k % 2 == 0 else {"circle": 0.4}
        bodies.append(h.body(shape, x, y, f"rider{k}", velocity=[3.0, 0.0], friction=0.4))
    return h.scene("Rolling terrain", "A smooth one-sided chain of 120 segments as ground: boxes slide and "
                                      "balls roll over it without catching on the joints.",
                   bodies, camera={"center": [0.0, 1.0], "zoom": 20.0})


def _compound_kinds(h):
    """Six bodies of several fixtures each, about 2 m across: two triangles (Box2D's compounds
    body, doubled), an L, a T, a dumbbell of two discs on a bar, a hammer and a cross."""
    box = (lambda hw, hh, cx=0.0, cy=0.0: {"polygon": _offset_box(hw, hh, cx, cy, h.r)})
    disc = (lambda rad, cx, cy: {"circle": {"radius": rad, "offset": [cx, cy]}})
    return {
        "twins": [{"polygon": [[-1.5, -1.0], [0.75, 0.5], [0.0, 2.0]]}, {"polygon": [[1.5, -1.0], [-0.75, 0.5], [0.0, 2.0]]}],
        "ell": [box(1.0, 0.25, 0.0, -0.75), box(0.25, 1.0, -0.75, 0.0)],
        "tee": [box(1.0, 0.25, 0.0, 0.75), box(0.25, 0.75, 0.0, -0.25)],
        "dumbbell": [disc(0.45, -0.8, 0.0), disc(0.45, 0.8, 0.0), box(0.8, 0.12)],
        "hammer": [box(0.15, 0.9, 0.0, -0.2), box(0.55, 0.3, 0.0, 0.85)],
        "cross": [box(0.9, 0.2), box(0.2, 0.9)],
    }


def compounds(h, columns=6, rows=5):
    """Thirty bodies of two or three fixtures each (six kinds) falling into a U of box fixtures on
    one static ground body: big enough to see that each is one rigid body of several shapes."""
    ground = [{"polygon": _offset_box(10.0, 0.5, 0.0, -0.5, h.r)},
              {"polygon": _offset_box(0.5, 5.0, -10.5, 4.0, h.r)}, {"polygon": _offset_box(0.5, 5.0, 10.5, 4.0, h.r)}]
    bodies = [{"name": "ground", "kind": "static", "shapes": ground, "position": [0.0, 0.0]}]
    kinds = _compound_kinds(h)
    names = list(kinds)
    rng = random.Random(7)
    for j in range(rows):
        for i in range(columns):
            kind = names[(i + 2 * j) % len(names)]
            x, y = -7.5 + 3.0 * i + (0.6 if j % 2 else 0.0), 2.0 + 3.2 * j
            bodies.append({"name": f"{kind}{j}_{i}", "shapes": kinds[kind], "position": [h.r(x), h.r(y)],
                           "angle": h.r(rng.uniform(-0.6, 0.6)), "friction": 0.5})
    return h.scene("Compounds", f"{columns * rows} compound bodies of six kinds (two triangles, an L, a T, a "
                                "dumbbell of two discs on a bar, a hammer, a cross), each one rigid body of "
                                "several fixtures, falling into a U of box fixtures on one static ground body.  "
                                "Try selecting one: the whole body lights up, and it tumbles as one.",
                   bodies, camera={"center": [0.0, 6.5], "zoom": 36.0})


def scenes(h) -> dict:
    """The scenes of this module as {file name: maker()}."""
    return {"tumbler": lambda: tumbler(h), "cup": lambda: cup(h), "capsules": lambda: capsules(h),
            "terrain": lambda: terrain(h), "compounds": lambda: compounds(h)}
