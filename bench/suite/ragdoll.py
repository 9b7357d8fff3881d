"""Box2D v3's ragdoll (``shared/human.c`` ``CreateHuman``) and its ragdoll ``rain`` benchmark.

A human is 11 capsule bodies (the lower legs also carry a rounded-polygon foot) on 10 revolute
joints with limits, joint friction (a motor at speed 0 whose max torque is the friction torque)
and an angular spring; shapes of one human share a negative collision group. ``rain``
(``CreateRain`` / ``StepRain``) drops rows of five humans every 8th step and, once 40 columns
stand, replaces the oldest column each time; the scripted creation and removal are
``bench.events`` of the description (applied before the step they name, inside the timed loop
as in Box2D's benchmark app).
"""
from __future__ import annotations

import math

from .common import body, box, capsule, hull, offset_box, polygon, scene

PI = math.pi
# bone: (parent, body y, capsule (y0, y1, r), pivot y, lower, upper limit (x pi), friction scale, damping)
BONES = {
    "hip": (None, 0.95, (-0.02, 0.02, 0.095), None, None, None, 1.0, 0.0),
    "torso": ("hip", 1.2, (-0.135, 0.135, 0.09), 1.0, -0.25, 0.0, 0.5, 0.0),
    "head": ("torso", 1.475, (-0.038, 0.039, 0.075), 1.4, -0.3, 0.1, 0.25, 0.1),
    "upper_left_leg": ("hip", 0.775, (-0.125, 0.125, 0.06), 0.9, -0.05, 0.4, 1.0, 0.0),
    "lower_left_leg": ("upper_left_leg", 0.475, (-0.155, 0.125, 0.045), 0.625, -0.5, -0.02, 0.5, 0.0),
    "upper_right_leg": ("hip", 0.775, (-0.125, 0.125, 0.06), 0.9, -0.05, 0.4, 1.0, 0.0),
    "lower_right_leg": ("upper_right_leg", 0.475, (-0.155, 0.125, 0.045), 0.625, -0.5, -0.02, 0.5, 0.0),
    "upper_left_arm": ("torso", 1.225, (-0.125, 0.125, 0.035), 1.35, -0.1, 0.8, 0.5, 0.0),
    "lower_left_arm": ("upper_left_arm", 0.975, (-0.125, 0.125, 0.03), 1.1, -0.2, 0.3, 0.1, 0.1),
    "upper_right_arm": ("torso", 1.225, (-0.125, 0.125, 0.035), 1.35, -0.1, 0.8, 0.5, 0.0),
    "lower_right_arm": ("upper_right_arm", 0.975, (-0.125, 0.125, 0.03), 1.1, -0.2, 0.3, 0.1, 0.1),
}
FOOT = [(-0.03, -0.185), (0.11, -0.185), (0.11, -0.16), (-0.03, -0.14)]


def human(prefix, x, y, scale=1.0, friction_torque=0.05, hertz=5.0, damping_ratio=0.5, group=1):
    """(bodies, joints) of one ragdoll standing at (x, y); names ``{prefix}{bone}``."""
    s = scale
    fil = {"category": 2, "mask": 1 | 2, "group": -group, "friction": 0.2}
    bodies, joints = [], []
    for name, (parent, by, (c0, c1, r), pivot, lo, hi, fscale, damp) in BONES.items():
        shapes = [capsule((0.0, c0 * s), (0.0, c1 * s), r * s, **fil)]
        if name.startswith("lower") and name.endswith("leg"):
            # feet do not collide with ragdolls (mask 1 only), and slide more
            shapes.append(polygon(hull([(px * s, py * s) for px, py in FOOT]), radius=0.015 * s, category=2, mask=1,
                                  group=-group, friction=0.05))
        ext = {"sleep_threshold": 0.1}
        if damp:
            ext["linear_damping"] = damp
        bodies.append(body(shapes, x, y + by * s, name=prefix + name, density=1.0, box2d=ext))
        if parent is None:
            continue
        j = {"kind": "revolute", "name": prefix + name, "a": prefix + name, "b": prefix + parent,
             "anchor": [x, y + pivot * s], "lower_angle": lo * PI, "upper_angle": hi * PI,
             "motor_speed": 0.0, "max_motor_torque": fscale * friction_torque * s,
             "spring_hertz": hertz, "spring_damping_ratio": damping_ratio}
        if name.startswith("lower") and name.endswith("arm"):
            j["reference_angle"] = 0.25 * PI  # Box2D: localFrameA.q = b2MakeRot(0.25 pi)
        joints.append(j)
    return bodies, joints


ROWS, COLUMNS, GROUP = 5, 40, 5
GRID, GRID_COUNT = 0.5, 500


def _group(row, col, gen):
    span = GRID_COUNT * GRID
    x = -0.5 * span + span / COLUMNS * (col + 0.5)
    y = 40.0 + 45.0 * row
    bodies, joints = [], []
    for i in range(GROUP):
        b, j = human(f"r{row}c{col}g{gen}h{i}_", x + 0.5 * i, y, group=i + 1)
        bodies += b
        joints += j
    return bodies, joints


def rain(steps=1000):
    """``CreateRain`` + ``StepRain``: ragdolls rained in groups of five onto five rows of ground
    boxes; up to 1,000 ragdolls (11,000 bodies) at once; sleeping on; 1000 steps."""
    ground = []
    for i in range(ROWS):
        x = -0.5 * GRID_COUNT * GRID
        for _ in range(GRID_COUNT + 1):
            ground.append(offset_box(0.5 * GRID, 0.5 * GRID, x, 45.0 * i, friction=0.6))
            x += GRID
    events, count, index, gen = [], 0, 0, {}
    for k in range(steps):
        if k & 7:
            continue
        if count < COLUMNS:
            cols, count = [count], count + 1
        else:
            cols, index = [index], (index + 1) % COLUMNS
        for row in range(ROWS):
            col = cols[0]
            remove = []
            if (row, col) in gen:
                g = gen[(row, col)]
                remove = [f"r{row}c{col}g{g}h{i}_{bone}" for i in range(GROUP) for bone in BONES]
            g = gen.get((row, col), -1) + 1
            gen[(row, col)] = g
            b, j = _group(row, col, g)
            events.append({"step": k, "remove": remove, "add": {"bodies": b, "joints": j}})
    return scene("rain", "ragdolls rained onto rows of ground boxes", [body(ground, kind="static", name="ground")],
                 sleeping=True, steps=steps, source="box2d-v3 shared/benchmarks.c CreateRain, StepRain; human.c",
                 bench={"events": events})


def standing_human():
    """One ragdoll on a ground box (a small joint scene for tests)."""
    b, j = human("", 0.0, 0.0)
    return scene("human", "one Box2D ragdoll on the ground", [body(box(10.0, 0.5), 0.0, -0.5, kind="static")] + b, j)
