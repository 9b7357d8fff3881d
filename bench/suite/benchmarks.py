"""Box2D v3's benchmark suite (``shared/benchmarks.c`` of the snapshot) as scene descriptions.

Each builder returns a scene dict with the same bodies, shapes, joints, materials, world settings
(sleeping on wherever ``benchmarks.c`` leaves Box2D's default on) and step count
(``bench.steps``, from ``benchmark/main.c``) as the C function it names. The ragdoll ``rain`` is
in ``ragdoll.py``. Capsules, segments, chains, rounded boxes, several shapes per body and joints
are written in the version-2 keys of issues 13 and 14; ``NEEDS`` (``__init__.py``) says what still
differs.
"""
from __future__ import annotations

import math

from .common import body, box, capsule, chain, circle, hull, offset_box, polygon, scene, segment

SRC = "box2d-v3 shared/benchmarks.c"


def _pyramid_boxes(base, extent, x0, y0, density=1.0):
    out = []
    for i in range(base):
        y = (2.0 * i + 1.0) * extent + y0
        for j in range(i, base):
            x = (i + 1.0) * extent + 2.0 * (j - i) * extent + x0
            out.append(body(box(extent, extent), x, y, density=density, friction=0.6))
    return out


def large_pyramid(base=100):
    """``CreateLargePyramid``: 5,050 unit boxes on a 200 x 2 static box; sleeping off; 500 steps."""
    ground = body(box(100.0, 1.0), 0.0, -1.0, kind="static", name="ground", friction=0.6)
    bodies = [ground] + _pyramid_boxes(base, 0.5, -0.5 * base, 0.0)
    return scene("large_pyramid", f"{len(bodies) - 1} boxes in a pyramid of base {base}", bodies,
                 steps=500, source=f"{SRC} CreateLargePyramid")


def many_pyramids(rows=20, columns=20, base=10):
    """``CreateManyPyramids``: 400 pyramids of 55 boxes on 20 ground segments; sleeping off; 200 steps."""
    extent = 0.5
    dy = 2.0 * extent * (base + 1.0)
    width = 2.0 * extent * columns * (base + 1.0)
    segs = [segment((-0.5 * width, i * dy), (0.5 * width, i * dy), friction=0.6) for i in range(rows)]
    bodies = [body(segs, kind="static", name="ground")]
    base_width = 2.0 * extent * base
    for i in range(rows):
        for j in range(columns):
            cx = -0.5 * width + j * (base_width + 2.0 * extent) + 2.0 * extent
            bodies += _pyramid_boxes(base, extent, cx - 0.5, i * dy)
    return scene("many_pyramids", f"{rows * columns} pyramids of {base * (base + 1) // 2} boxes", bodies,
                 steps=200, source=f"{SRC} CreateManyPyramids")


def smash(columns=120, rows=80):
    """``CreateSmash``: a dense 8x8 box at 40 m/s into 9,600 sleeping 0.4 m boxes; zero gravity; 300 steps."""
    bodies = [body(box(4.0, 4.0), -20.0, 0.0, velocity=(40.0, 0.0), density=8.0, friction=0.6, name="ram")]
    d = 0.4
    for i in range(columns):
        for j in range(rows):
            bodies.append(body(box(0.5 * d, 0.5 * d), i * d + 30.0, (j - rows / 2.0) * d, friction=0.6,
                               awake=False))
    return scene("smash", "a heavy box smashes a wall of sleeping boxes", bodies, gravity=(0.0, 0.0),
                 sleeping=True, steps=300, source=f"{SRC} CreateSmash")


def joint_grid(n=100):
    """``CreateJointGrid``: 100 x 100 discs (r 0.4) on ~19,800 revolute joints, 7 pinned; sleeping off; 500 steps."""
    bodies, joints = [], []
    for k in range(n):
        for i in range(n):
            static = n // 2 - 3 <= k <= n // 2 + 3 and i == 0
            bodies.append(body(circle(0.4, category=2, mask=0xFFFFFFFD), float(k), -float(i),
                               kind="static" if static else "dynamic", name=f"g{k}_{i}", density=1.0, friction=0.6))
            if i > 0:
                joints.append({"kind": "revolute", "a": f"g{k}_{i}", "b": f"g{k}_{i - 1}", "anchor": [k, 0.5 - i]})
            if k > 0:
                joints.append({"kind": "revolute", "a": f"g{k}_{i}", "b": f"g{k - 1}_{i}", "anchor": [k - 0.5, -i]})
    return scene("joint_grid", f"{n * n} discs on revolute joints", bodies, joints, steps=500,
                 source=f"{SRC} CreateJointGrid")


def spinner(count=2 * 3038):
    """``CreateSpinner``: 6,076 capsules, discs and squares stirred by a motorised rounded bar inside a
    360-point chain loop; sleeping on (the spinner never sleeps); 500 steps."""
    pts = [(40.0 * math.cos(-2 * math.pi * i / 360), 40.0 * math.sin(-2 * math.pi * i / 360) + 32.0)
           for i in range(360)]
    ground = body(chain(pts, loop=True, friction=0.1, restitution=0.0), kind="static", name="ground")
    bar = body(box(0.4, 20.0, radius=0.2, friction=0.0), 0.0, 12.0, name="spinner", box2d={"enable_sleep": False})
    bodies = [ground, bar]
    shapes = (capsule((-0.25, 0.0), (0.25, 0.0), 0.25), circle(0.35), box(0.35, 0.35))
    x, y = -23.0, 2.0
    for i in range(count):
        bodies.append(body(shapes[i % 3], x, y, density=0.25, friction=0.1, restitution=0.1))
        x += 0.5
        if x >= 23.0:
            x, y = -23.0, y + 0.5
    joints = [{"kind": "revolute", "name": "motor", "a": "spinner", "b": None, "anchor": [0.0, 12.0],
               "motor_speed": 5.0, "max_motor_torque": 3.4e38}]
    return scene("spinner", f"{count} bodies stirred in a chain loop", bodies, joints, sleeping=True, steps=500,
                 source=f"{SRC} CreateSpinner")


def tumbler(grid=45):
    """``CreateTumbler``: a dynamic hollow box (four boxes, density 50) turned at 25 deg/s by a motor,
    2,025 small boxes inside; sleeping on; 750 steps."""
    walls = [offset_box(0.5, 10.0, 10.0, 0.0), offset_box(0.5, 10.0, -10.0, 0.0),
             offset_box(10.0, 0.5, 0.0, 10.0), offset_box(10.0, 0.5, 0.0, -10.0)]
    bodies = [body(walls, 0.0, 10.0, name="drum", density=50.0, friction=0.6)]
    y = -0.2 * grid + 10.0
    for _ in range(grid):
        x = -0.2 * grid
        for _ in range(grid):
            bodies.append(body(box(0.125, 0.125), x, y, density=1.0, friction=0.6))
            x += 0.4
        y += 0.4
    joints = [{"kind": "revolute", "name": "motor", "a": "drum", "b": None, "anchor": [0.0, 10.0],
               "motor_speed": math.pi / 180.0 * 25.0, "max_motor_torque": 1e8}]
    return scene("tumbler", f"{grid * grid} boxes in a motorised drum", bodies, joints, sleeping=True, steps=750,
                 source=f"{SRC} CreateTumbler")


def _washer_drum():
    r0, r1, r2 = 14.0, 16.0, 18.0
    step, lip = math.pi / 18.0, 0.1 * math.pi / 18.0
    parts = []
    for i in range(36):
        t1, t2 = i * step, (0.0 if i == 35 else (i + 1) * step)
        u1, u2 = (math.cos(t1), math.sin(t1)), (math.cos(t2), math.sin(t2))
        a1, a2 = (math.cos(t1 - lip), math.sin(t1 - lip)), (math.cos(t2 + lip), math.sin(t2 + lip))
        ring = [(r1 * a1[0], r1 * a1[1]), (r2 * a1[0], r2 * a1[1]), (r1 * a2[0], r1 * a2[1]), (r2 * a2[0], r2 * a2[1])]
        parts.append(polygon(hull(ring), friction=0.6))
        if i % 9 == 0:
            paddle = [(r0 * u1[0], r0 * u1[1]), (r1 * u1[0], r1 * u1[1]), (r0 * u2[0], r0 * u2[1]),
                      (r1 * u2[0], r1 * u2[1])]
            parts.append(polygon(hull(paddle), friction=0.6))
    return parts


def washer(grid=90):
    """``CreateWasher``: a kinematic ring of 40 polygons turning at 25 deg/s (and drifting 1-2 mm/s),
    8,100 boxes of 0.2 m with hit events; sleeping on; 500 steps."""
    drum = body(_washer_drum(), 0.0, 10.0, kind="kinematic", name="drum", velocity=(0.001, -0.002),
                angular_velocity=math.pi / 180.0 * 25.0)
    bodies = [drum]
    a = 0.1
    y = -1.1 * a * grid + 10.0
    for _ in range(grid):
        x = -1.1 * a * grid
        for _ in range(grid):
            bodies.append(body(box(a, a, box2d={"hit_events": True}), x, y, density=1.0, friction=0.6))
            x += 2.1 * a
        y += 2.1 * a
    return scene("washer", f"{grid * grid} boxes in a turning kinematic drum", bodies, sleeping=True, steps=500,
                 source=f"{SRC} CreateWasher")


def _walls(floor_count, wall_count, half_span):
    parts = [offset_box(0.55, 0.5, -half_span + i, 0.0, friction=0.6) for i in range(floor_count)]
    for x in (-half_span, half_span):
        parts += [offset_box(0.5, 0.55, x, 1.0 + i, friction=0.6) for i in range(wall_count)]
    return parts


def junkyard(columns=200, rows=40):
    """``CreateJunkyard``: 8,000 pentagons in a box-walled yard, swept by a kinematic pusher driven to
    x = 60 sin(0.2 t) each step; sleeping on; 800 steps."""
    bodies = [body(_walls(161, 50, 80.0), kind="static", name="ground")]
    radius = 0.25
    phi = math.pi * (math.sqrt(5.0) - 1.0)
    pent = polygon(hull([(radius * math.cos(phi * i), radius * math.sin(phi * i)) for i in range(5)]))
    side = -0.1
    for i in range(columns):
        x = 1.5 * (2.0 * i - columns) * radius
        for j in range(rows):
            bodies.append(body(pent, x + side, 4.0 * j * radius + 15.0, density=1.0, friction=0.6))
            side = -side
    bodies.append(body(offset_box(2.0, 4.0, 0.0, 4.0), 0.0, 0.0, kind="kinematic", name="pusher"))
    drives = [{"body": "pusher", "kind": "sine_target", "center": [0.0, 0.0], "amplitude": [60.0, 0.0],
               "omega": 0.2}]
    return scene("junkyard", f"{columns * rows} pentagons swept by a kinematic pusher", bodies, sleeping=True,
                 steps=800, source=f"{SRC} CreateJunkyard, StepJunkyard", bench={"drives": drives})


def compounds(columns=20, rows=150):
    """``CreateCompounds``: 3,000 bodies of two triangles each (friction 0.5) falling into a box-walled
    pit; sleeping on; 500 steps."""
    ground = _walls(81, 100, 40.0) + [segment((-800.0, -80.0), (800.0, -80.0), friction=0.6)]
    bodies = [body(ground, kind="static", name="ground")]
    left = polygon(hull([(-1.0, 0.0), (0.5, 1.0), (0.0, 2.0)]))
    right = polygon(hull([(1.0, 0.0), (-0.5, 1.0), (0.0, 2.0)]))
    shift, extray, side = 2.0, 0.25, 0.25
    cx, cy = shift * columns / 2.0 - 1.0, 1.15 / 2.0
    for i in range(columns):
        x = i * shift - cx
        for j in range(rows):
            bodies.append(body([left, right], x + side, j * (shift + extray) + cy + 5.0, density=1.0, friction=0.5))
            side = -side
    return scene("compounds", f"{columns * rows} two-triangle compound bodies", bodies, sleeping=True, steps=500,
                 source=f"{SRC} CreateCompounds")
