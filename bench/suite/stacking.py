"""Box2D v3's Stacking samples (``samples/sample_stacking.cpp``) as scene descriptions.

Same bodies, shapes, materials and world tuning as each sample's constructor (the sample app's
defaults: gravity -10, density 1, friction 0.6, restitution 0; the issue-18 conditions: dt 1/60,
4 sub-steps, sleeping off). Bodies the measurements follow are named (``top``, ``box`` ...).
"""
from __future__ import annotations

import math

from .common import body, box, capsule, circle, hull, offset_box, polygon, scene, segment

SRC = "box2d-v3 samples/sample_stacking.cpp"


def single_box():
    """``SingleBox``: a 2 m box sliding at 5 m/s on a 132 m ground segment (friction 0.6)."""
    bodies = [body(segment((-66.0, 0.0), (66.0, 0.0), friction=0.6), kind="static", name="ground"),
              body(box(1.0, 1.0), 0.0, 1.0, velocity=(5.0, 0.0), name="box", friction=0.6)]
    return scene("Single Box", "a 2 m box launched at 5 m/s along the ground", bodies, source=f"{SRC} SingleBox")


def tilted_stack(columns=10, rows=10):
    """``TiltedStack``: 10 columns of 10 rounded 1 m boxes (friction 0.3), each row 0.2 m further right."""
    bodies = [body(box(1000.0, 1.0), 0.0, -1.0, kind="static", name="ground", friction=0.6)]
    dx = 5.0
    for j in range(columns):
        x = -0.5 * dx * (columns - 1.0) + j * dx
        for i in range(rows):
            name = f"top{j}" if i == rows - 1 else None
            bodies.append(body(box(0.45, 0.45, radius=0.05), x + 0.2 * i, 0.5 + i, name=name, density=1.0,
                               friction=0.3))
    return scene("Tilted Stack", "ten leaning stacks of rounded boxes", bodies, source=f"{SRC} TiltedStack")


def vertical_stack(rows=12):
    """``VerticalStack`` (its default: one column of 12 rounded 1 m boxes, friction 0.3, shifted +-1 cm)."""
    ground = [segment((10.0, 0.0), (10.0, 20.0), friction=0.6), segment((-30.0, 0.0), (30.0, 0.0), friction=0.6)]
    bodies = [body(ground, kind="static", name="ground")]
    for i in range(rows):
        shift = -0.01 if i % 2 == 0 else 0.01
        bodies.append(body(box(0.45, 0.45, radius=0.05), 8.0 + shift, 0.5 + i, density=1.0, friction=0.3,
                           name="top" if i == rows - 1 else None))
    return scene("Vertical Stack", f"a column of {rows} rounded boxes", bodies, source=f"{SRC} VerticalStack")


def circle_stack():
    """``CircleStack``: four frictionless discs (e 0.8, density 1, 5, 9, 13) dropped in a column;
    gravity -20, contact tuning 90 Hz / damping 10 / push 3 m/s."""
    bodies = [body(segment((-10.0, 0.0), (10.0, 0.0), friction=0.6), kind="static", name="ground")]
    y = 0.75
    for i in range(4):
        bodies.append(body(circle(0.5), 0.0, y, density=1.0 + 4.0 * i, friction=0.0, restitution=0.8,
                           name="top" if i == 3 else f"c{i}"))
        y += 1.25
    return scene("Circle Stack", "four bouncing discs settling into a column", bodies, gravity=(0.0, -20.0),
                 box2d={"contact_hertz": 0.25 * 360.0, "contact_damping_ratio": 10.0, "contact_speed": 3.0},
                 source=f"{SRC} CircleStack")


def capsule_stack(count=20):
    """``CapsuleStack``: 20 capsules (2 m core, radius 0.25) dropped 0.25 m apart in a column."""
    bodies = [body(box(10.0, 1.0), 0.0, -1.0, kind="static", name="ground", friction=0.6)]
    a = 0.25
    y = 2.0 * a
    for i in range(count):
        bodies.append(body(capsule((-4 * a, 0.0), (4 * a, 0.0), a), 0.0, y, density=1.0, friction=0.6,
                           name="top" if i == count - 1 else None))
        y += 3.0 * a
    return scene("Capsule Stack", f"{count} capsules in a column", bodies, source=f"{SRC} CapsuleStack")


def cliff():
    """``Cliff`` (not flipped): capsules, squares and discs sliding off a segment, a box and a capsule ledge."""
    ground = [offset_box(100.0, 1.0, 0.0, -1.0, friction=0.6), segment((-14.0, 4.0), (-8.0, 4.0), friction=0.6),
              offset_box(3.0, 0.5, 0.0, 4.0, friction=0.6), capsule((8.5, 4.0), (13.5, 4.0), 0.5, friction=0.6)]
    bodies = [body(ground, kind="static", name="ground")]
    cap, disc, sq = capsule((-0.25, 0.0), (0.25, 0.0), 0.25), circle(0.5), box(0.5, 0.5)
    for i, (x, y) in enumerate(((-9.0, 4.25), (2.0, 4.75), (13.0, 4.75))):
        bodies.append(body(cap, x, y, velocity=(2.0, 0.0), friction=0.01, density=1.0, name=f"capsule{i}"))
    for i, (x, y) in enumerate(((-11.0, 4.5), (0.0, 5.0), (11.0, 5.0))):
        bodies.append(body(sq, x, y, velocity=(2.5, 0.0), friction=0.01, density=1.0, name=f"square{i}"))
    for i, (x, y) in enumerate(((-13.0, 4.5), (-2.0, 5.0), (9.0, 5.0))):
        bodies.append(body(disc, x, y, velocity=(1.5, 0.0), friction=0.2, density=1.0, name=f"disc{i}"))
    return scene("Cliff", "bodies sliding off three kinds of ledge", bodies, source=f"{SRC} Cliff")


ARCH_PS1 = [(16.0, 0.0), (14.93803712795643, 5.133601056842984), (13.79871746027416, 10.24928069555078),
            (12.56252963284711, 15.34107019122473), (11.20040987372525, 20.39856541571217),
            (9.66521217819836, 25.40369899225096), (7.87179930638133, 30.3179337000085),
            (5.635199558196225, 35.03820717801641), (2.405937953536585, 39.09554102558315)]
ARCH_PS2 = [(24.0, 0.0), (22.33619528222415, 6.02299846205841), (20.54936888969905, 12.00964361211476),
            (18.60854610798073, 17.9470321677465), (16.46769273811807, 23.81367936585418),
            (14.05325025774858, 29.57079353071012), (11.23551045834022, 35.13775818285372),
            (7.752568160730571, 40.30450679009583), (3.016931552701656, 44.28891593799322)]


def arch():
    """``Arch``: 17 general convex quads (scale 0.25, friction 0.6) forming an arch, four 4 x 1 boxes on top."""
    p1 = [(0.25 * x, 0.25 * y) for x, y in ARCH_PS1]
    p2 = [(0.25 * x, 0.25 * y) for x, y in ARCH_PS2]
    bodies = [body(segment((-100.0, 0.0), (100.0, 0.0), friction=0.6), kind="static", name="ground")]
    for i in range(8):
        bodies.append(body(polygon(hull([p1[i], p2[i], p2[i + 1], p1[i + 1]])), friction=0.6, density=1.0))
    for i in range(8):
        q = [(-p2[i][0], p2[i][1]), (-p1[i][0], p1[i][1]), (-p1[i + 1][0], p1[i + 1][1]), (-p2[i + 1][0], p2[i + 1][1])]
        bodies.append(body(polygon(hull(q)), friction=0.6, density=1.0))
    key = [p1[8], p2[8], (-p2[8][0], p2[8][1]), (-p1[8][0], p1[8][1])]
    bodies.append(body(polygon(hull(key)), friction=0.6, density=1.0, name="keystone"))
    for i in range(4):
        bodies.append(body(box(2.0, 0.5), 0.0, 0.5 + p2[8][1] + 1.0 * i, friction=0.6, density=1.0,
                           name="top" if i == 3 else None))
    return scene("Arch", "an arch of 17 voussoirs carrying four boxes", bodies, source=f"{SRC} Arch")


def double_domino(count=15):
    """``DoubleDomino``: 15 dominoes 0.25 x 1 m (friction 0.6); the first is struck by an impulse of
    0.2 N s at its top (given here as its resulting velocities, exactly what the impulse produces)."""
    bodies = [body(box(100.0, 1.0), 0.0, -1.0, kind="static", name="ground", friction=0.6)]
    m = 0.25 * 1.0
    inertia = m * (0.25 ** 2 + 1.0) / 12.0
    x = -0.5 * count
    for i in range(count):
        v, w = ((0.2 / m, 0.0), (0.5 * -0.2) / inertia) if i == 0 else ((0.0, 0.0), 0.0)
        bodies.append(body(box(0.125, 0.5), x, 0.5, velocity=v, angular_velocity=w, friction=0.6, density=1.0,
                           name=f"d{i}"))
        x += 1.0
    return scene("Double Domino", f"{count} dominoes, the first pushed at its top", bodies,
                 source=f"{SRC} DoubleDomino")


def confined(grid=25):
    """``Confined``: 625 discs (r 0.5) created overlapping in a 25 x 25 grid inside a closed box of
    capsules, without gravity (the sample gives each body gravity scale 0; the world here has none)."""
    walls = [capsule((-10.5, 0.0), (10.5, 0.0), 0.5), capsule((-10.5, 0.0), (-10.5, 20.5), 0.5),
             capsule((10.5, 0.0), (10.5, 20.5), 0.5), capsule((-10.5, 20.5), (10.5, 20.5), 0.5)]
    bodies = [body([dict(w, friction=0.6) for w in walls], kind="static", name="ground")]
    for col in range(grid):
        for row in range(grid):
            bodies.append(body(circle(0.5), -8.75 + col * 18.0 / grid, 1.5 + row * 18.0 / grid, density=1.0,
                               friction=0.6))
    return scene("Confined", f"{grid * grid} overlapping discs in a closed box, no gravity", bodies,
                 gravity=(0.0, 0.0), source=f"{SRC} Confined")


def card_house():
    """``CardHouse`` (from PEEL): cards 2 mm x 0.4 m (friction 0.7) leaning at +-25 degrees, flat cards
    across, five storeys on a static box."""
    bodies = [body(box(40.0, 2.0), 0.0, -2.0, kind="static", name="ground", friction=0.7)]
    h, t = 0.2, 0.001
    a0, a1, a2 = math.radians(25.0), math.radians(-25.0), 0.5 * math.pi
    card = box(t, h)
    nb, z0, y = 5, 0.0, h - 0.02
    while nb:
        z = z0
        for i in range(nb):
            if i != nb - 1:
                bodies.append(body(card, z + 0.25, y + h - 0.015, angle=a2, friction=0.7, density=1.0))
            bodies.append(body(card, z, y, angle=a1, friction=0.7, density=1.0))
            z += 0.175
            bodies.append(body(card, z, y, angle=a0, friction=0.7, density=1.0))
            z += 0.175
        y += 2.0 * h - 0.03
        z0 += 0.175
        nb -= 1
    bodies[-1]["name"] = "top"
    return scene("Card House", "five storeys of 2 mm x 0.4 m cards", bodies, source=f"{SRC} CardHouse")
