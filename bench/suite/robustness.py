"""Box2D v3's Robustness samples (``samples/sample_robustness.cpp``) as scene descriptions."""
from __future__ import annotations

from .common import body, box, circle, hull, offset_box, polygon, scene, segment

SRC = "box2d-v3 samples/sample_robustness.cpp"


def _ground50():
    return body(offset_box(50.0, 1.0, 0.0, -1.0, friction=0.6), kind="static", name="ground")


def high_mass_ratio_1():
    """``HighMassRatio1``: three 10-row pyramids of 2 m boxes; each top box 2 m higher and 100, 200,
    300 times denser than the rest."""
    bodies = [_ground50()]
    for j in range(3):
        count, y = 10, 1.0
        offset = -20.0 + 2.0 * (count + 1.0) * j
        while count > 0:
            for i in range(count):
                coeff = i - 0.5 * count
                top = count == 1
                bodies.append(body(box(1.0, 1.0), 2.0 * coeff + offset, y + 2.0 if top else y,
                                   density=(j + 1.0) * 100.0 if top else 1.0, friction=0.6,
                                   name=f"top{j}" if top else None))
            count -= 1
            y += 2.0
    return scene("HighMassRatio1", "three pyramids with 100-300x denser top boxes", bodies,
                 source=f"{SRC} HighMassRatio1")


def high_mass_ratio_2():
    """``HighMassRatio2``: a 20 m box (400 kg) dropped 15 m onto two 1 m boxes 18 m apart."""
    bodies = [_ground50(),
              body(box(0.5, 0.5), -9.0, 0.5, friction=0.6, density=1.0, name="left"),
              body(box(0.5, 0.5), 9.0, 0.5, friction=0.6, density=1.0, name="right"),
              body(box(10.0, 10.0), 0.0, 26.0, friction=0.6, density=1.0, name="big")]
    return scene("HighMassRatio2", "a big box falls onto two small boxes", bodies, source=f"{SRC} HighMassRatio2")


def high_mass_ratio_3():
    """``HighMassRatio3``: a 20 m box (400 kg) dropped onto two small triangles (base 1, height 1)."""
    tri = polygon(hull([(-0.5, 0.0), (0.5, 0.0), (0.0, 1.0)]))
    bodies = [_ground50(),
              body(tri, -9.0, 0.5, friction=0.6, density=1.0, name="left"),
              body(tri, 9.0, 0.5, friction=0.6, density=1.0, name="right"),
              body(box(10.0, 10.0), 0.0, 14.0, friction=0.6, density=1.0, name="big")]
    return scene("HighMassRatio3", "a big box falls onto two small triangles", bodies, source=f"{SRC} HighMassRatio3")


def overlap_recovery(base=4, overlap=0.25, extent=0.5):
    """``OverlapRecovery``: a 4-base pyramid of 1 m boxes created 25 % overlapping; contact tuning
    30 Hz, damping 10, push-out 3 m/s (the sample's)."""
    bodies = [body(segment((-40.0, 0.0), (40.0, 0.0), friction=0.6), kind="static", name="ground")]
    frac = 1.0 - overlap
    y = extent
    for i in range(base):
        x = frac * extent * (i - base)
        for j in range(i, base):
            bodies.append(body(box(extent, extent), x, y, density=1.0, friction=0.6,
                               name="top" if i == base - 1 else None))
            x += 2.0 * frac * extent
        y += 2.0 * frac * extent
    return scene("Overlap Recovery", "a pyramid created 25 % overlapping pushes itself apart", bodies,
                 box2d={"contact_hertz": 30.0, "contact_damping_ratio": 10.0, "contact_speed": 3.0},
                 source=f"{SRC} OverlapRecovery")


def tiny_pyramid(base=30, extent=0.025):
    """``TinyPyramid``: 465 boxes of 5 cm in a pyramid of base 30 on a 10 x 2 m static box."""
    bodies = [body(offset_box(5.0, 1.0, 0.0, -1.0, friction=0.6), kind="static", name="ground")]
    for i in range(base):
        y = (2.0 * i + 1.0) * extent
        for j in range(i, base):
            x = (i + 1.0) * extent + 2.0 * (j - i) * extent - base * extent
            bodies.append(body(box(extent, extent), x, y, density=1.0, friction=0.6,
                               name="top" if i == base - 1 else None))
    return scene("Tiny Pyramid", f"{base * (base + 1) // 2} boxes of {200 * extent:g} cm", bodies,
                 source=f"{SRC} TinyPyramid")


def cart(substeps=4):
    """``Cart``: a 1000 kg/m^2 chassis on two 0.1 m wheels (density 50, rolling resistance 0.02) on
    revolute joints tuned to 240 Hz / damping 0; gravity -22; contact tuning 240 Hz / 10 / 0.5 m/s.
    The sample runs 12 sub-steps; issue 18's conditions are 4 (``substeps``)."""
    y0 = 2.0
    bodies = [body(box(20.0, 1.0), 0.0, -1.0, kind="static", name="ground", friction=0.6),
              body(offset_box(1.0, 0.25, 0.0, 0.25), 0.0, y0, density=1000.0, friction=0.6, name="chassis")]
    wheel = circle(0.1, box2d={"rolling_resistance": 0.02})
    bodies += [body(wheel, -0.9, y0 - 0.15, density=50.0, friction=0.6, name="wheel1"),
               body(wheel, 0.9, y0 - 0.15, density=50.0, friction=0.6, name="wheel2")]
    tune = {"constraint_hertz": 240.0, "constraint_damping_ratio": 0.0}
    joints = [{"kind": "revolute", "name": f"axle{k}", "a": f"wheel{k}", "b": "chassis",
               "anchor": [x, y0 - 0.15], "box2d": tune} for k, x in ((1, -0.9), (2, 0.9))]
    return scene("Cart", "a heavy cart on small wheels under high gravity", bodies, joints, gravity=(0.0, -22.0),
                 substeps=substeps,
                 box2d={"contact_hertz": 240.0, "contact_damping_ratio": 10.0, "contact_speed": 0.5},
                 source=f"{SRC} Cart")


def multiple_prismatic(count=6):
    """``MultiplePrismatic``: six 1 m boxes 1.2 m apart in a column, each on a prismatic joint (horizontal
    axis, limits +-6 m, joint tuning 240 Hz) to the one below, the lowest to the world."""
    bodies, joints = [], []
    for i in range(count):
        bodies.append(body(box(0.5, 0.5), 0.0, 0.6 + 1.2 * i, density=1.0, friction=0.6,
                           name="top" if i == count - 1 else f"p{i}"))
        joints.append({"kind": "prismatic", "a": bodies[-1]["name"], "b": None if i == 0 else f"p{i - 1}",
                       "anchor": [0.0, 1.2 * i], "axis": [1.0, 0.0], "lower": -6.0, "upper": 6.0,
                       "box2d": {"constraint_hertz": 240.0}})
    # the sample has no ground shape: the column hangs on its joints
    return scene("Multiple Prismatic", "a column of boxes on stacked prismatic joints", bodies, joints,
                 source=f"{SRC} MultiplePrismatic")
