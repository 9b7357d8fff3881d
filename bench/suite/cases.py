"""Accuracy cases beyond Box2D's samples (issue 18) and the joint cases of issue 14, as descriptions.

Geometry follows bench/reliability.py where that already defines the case (1000:1 stack, 1 cm
boxes), so figures compare with docs/reliability.md; all run at dt 1/60, 4 sub-steps, sleeping off.
"""
from __future__ import annotations

import math

from .common import body, box, circle, scene

G = -10.0


def _ground(width=200.0, thickness=1.0, top=0.0, **mat):
    return body(box(0.5 * width, 0.5 * thickness), 0.0, top - 0.5 * thickness, kind="static", name="ground",
                friction=0.6, **mat)


def mass_ratio_1000():
    """A 1000 kg box (1 x 1 m, density 1000) resting on a 1 kg box (1 x 1 m) on static ground
    (bench/reliability.py ``mass_ratio_stack``; gravity -9.81 as there)."""
    bodies = [_ground(), body(box(0.5, 0.5), 0.0, 0.5, density=1.0, name="light", friction=0.6),
              body(box(0.5, 0.5), 0.0, 1.5, density=1000.0, name="heavy", friction=0.6)]
    return scene("1000:1 stack", "1000 kg box on a 1 kg box", bodies, gravity=(0.0, -9.81))


def restitution_drop(height=1.0, corner=False, e=0.5):
    """A 1 x 1 box (e = 0.5, friction 0.6) released at rest with its lowest point ``height`` above a
    static ground (e = 0: a contact uses the max, 0.5); ``corner``: turned 45 degrees, so it lands on a
    corner straight below its centre of mass (no torque at impact: the ideal rise is still e^2 h)."""
    half = math.sqrt(0.5) if corner else 0.5
    bodies = [_ground(restitution=0.0),
              body(box(0.5, 0.5), 0.0, height + half, angle=math.pi / 4 if corner else 0.0, density=1.0,
                   restitution=e, friction=0.6, name="box")]
    return scene(f"drop {height:g} m {'corner' if corner else 'flat'}", "restitution drop", bodies, gravity=(0.0, G))


def small_stack(size=0.01, count=5):
    """Five 1 cm boxes stacked touching on a static ground 40 sizes wide and one size thick
    (bench/reliability.py ``scaled_stack``; gravity -9.81 as there)."""
    bodies = [body(box(20 * size, 0.5 * size), 0.0, -0.5 * size, kind="static", name="ground", friction=0.6)]
    for i in range(count):
        bodies.append(body(box(0.5 * size, 0.5 * size), 0.0, size * (i + 0.5), density=1.0, friction=0.6,
                           name="top" if i == count - 1 else f"b{i}"))
    return scene("five 1 cm boxes", "five 0.01 m boxes stacked", bodies, gravity=(0.0, -9.81))


# -- joints (issue 14) ---------------------------------------------------------------------------
def rod_pendulum(length=1.0, width=0.05, theta0=0.05):
    """A rod (box ``length`` x ``width``, density 1) hinged to the world at one end, released at rest
    ``theta0`` rad from hanging straight down."""
    c, s = math.cos(theta0), math.sin(theta0)
    cx, cy = 0.5 * length * s, -0.5 * length * c
    rod = body(box(0.5 * width, 0.5 * length), cx, cy, angle=theta0, density=1.0, name="rod")
    joints = [{"kind": "revolute", "name": "hinge", "a": "rod", "b": None, "anchor": [0.0, 0.0]}]
    return scene("rod pendulum", "a rod swinging on a hinge", [rod], joints, gravity=(0.0, G))


def disc_pendulum(length=1.0, radius=0.1, theta0=0.05):
    """A disc (r 0.1, density 1) on a rigid distance joint of ``length`` from a world point to its
    centre, released at rest ``theta0`` from straight down (the disc turns freely: a point pendulum)."""
    x, y = length * math.sin(theta0), -length * math.cos(theta0)
    disc = body(circle(radius), x, y, density=1.0, name="disc")
    joints = [{"kind": "distance", "name": "rod", "a": "disc", "b": None, "anchor_a": [x, y], "anchor_b": [0.0, 0.0]}]
    return scene("disc pendulum", "a disc on a rigid distance joint", [disc], joints, gravity=(0.0, G))


def hanging_chain(links=50, length=0.5, width=0.1, weight_ratio=0.0):
    """``links`` links (box ``width`` x ``length``, density 1) hanging straight down from the world on
    revolute joints at their ends; ``weight_ratio`` > 0 hangs a 0.5 m box that many times a link's
    mass from the last link."""
    bodies, joints = [], []
    for i in range(links):
        bodies.append(body(box(0.5 * width, 0.5 * length), 0.0, -0.5 * length - i * length, density=1.0,
                           name=f"l{i}"))
        joints.append({"kind": "revolute", "name": f"j{i}", "a": f"l{i}", "b": None if i == 0 else f"l{i - 1}",
                       "anchor": [0.0, -i * length]})
    if weight_ratio:
        m_link = width * length
        y = -links * length - 0.25
        bodies.append(body(box(0.25, 0.25), 0.0, y, density=weight_ratio * m_link / 0.25, name="weight"))
        joints.append({"kind": "revolute", "name": "jw", "a": "weight", "b": f"l{links - 1}",
                       "anchor": [0.0, -links * length]})
    return scene(f"hanging chain {links}", "a chain of links on hinges", bodies, joints, gravity=(0.0, G))


def horizontal_chain(links=30, length=0.5, width=0.1):
    """``links`` links (``length`` x ``width``, density 1) laid out horizontally from a world hinge at
    the origin, released at rest."""
    bodies, joints = [], []
    for i in range(links):
        bodies.append(body(box(0.5 * length, 0.5 * width), 0.5 * length + i * length, 0.0, density=1.0,
                           name=f"l{i}"))
        joints.append({"kind": "revolute", "name": f"j{i}", "a": f"l{i}", "b": None if i == 0 else f"l{i - 1}",
                       "anchor": [i * length, 0.0]})
    return scene(f"horizontal chain {links}", "a chain released horizontal", bodies, joints, gravity=(0.0, G))


def weld_cantilever(count=10, length=1.0, height=0.25):
    """Ten 1 x 0.25 m boxes (density 1) welded rigidly (hertz 0) end to end, the first to the world at x = 0."""
    bodies, joints = [], []
    for i in range(count):
        bodies.append(body(box(0.5 * length, 0.5 * height), (i + 0.5) * length, 0.0, density=1.0, name=f"b{i}"))
        joints.append({"kind": "weld", "name": f"w{i}", "a": f"b{i}", "b": None if i == 0 else f"b{i - 1}",
                       "anchor": [i * length, 0.0]})
    return scene("weld cantilever", "ten welded boxes held at one end", bodies, joints, gravity=(0.0, G))


def wheel_suspension(hertz=4.0, damping=0.0):
    """A 1 x 0.5 m chassis (density 1) on a wheel joint to a world point (vertical axis, spring
    ``hertz``, no damping, no motor): it bobs on the spring about its sagged equilibrium."""
    chassis = body(box(0.5, 0.25), 0.0, 1.0, density=1.0, name="chassis")
    joints = [{"kind": "wheel", "name": "wheel", "a": "chassis", "b": None, "anchor": [0.0, 1.0], "axis": [0.0, 1.0],
               "spring_hertz": hertz, "spring_damping_ratio": damping}]
    return scene("wheel suspension", "a chassis bobbing on a wheel joint's spring", [chassis], joints,
                 gravity=(0.0, G))


def hanging_body(mass=1.0):
    """A 1 x 1 box of ``mass`` kg hanging at rest from a world hinge at its top edge centre."""
    b = body(box(0.5, 0.5), 0.0, -0.5, density=mass, name="box")
    joints = [{"kind": "revolute", "name": "pin", "a": "box", "b": None, "anchor": [0.0, 0.0]}]
    return scene("hanging body", "a box hanging on a hinge", [b], joints, gravity=(0.0, G))
