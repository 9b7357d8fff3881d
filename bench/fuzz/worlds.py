"""One random extreme world and its run plan, drawn from a seeded random.Random."""
from __future__ import annotations

import math
import random
from dataclasses import dataclass, field

import physics

DENSITY = (-6.0, 6.0)  # log10 kg/m^2
SPEED = (-2.0, 5.0)  # log10 m/s
STIFFNESS = (0.0, 9.0)  # log10 N/m
DT = (-5.0, 0.0)  # log10 s
SIZE = (-2.0, 1.0)  # log10 m


@dataclass
class Plan:
    """What a case runs: its world, steps, the step at which the mode switches (or -1) and to what."""
    world: physics.World
    steps: int
    switch_at: int = -1
    switch_to: str = ""
    overlapping: bool = False  # bodies may start inside each other (push-out may add energy)
    driven: bool = False  # a motor or mouse joint: external input, no energy invariant
    notes: list = field(default_factory=list)


def log_uniform(rnd, lo_hi) -> float:
    return 10.0 ** rnd.uniform(*lo_hi)


def shape(rnd):
    """A box, a circle or a regular polygon of 10 mm .. 10 m; returns (shape, bounding radius)."""
    s = log_uniform(rnd, SIZE)
    pick = rnd.random()
    if pick < 0.4:
        w, h = s, s * 10.0 ** rnd.uniform(-1.0, 1.0)
        return physics.Polygon.box(w, h), 0.5 * math.hypot(w, h)
    if pick < 0.7:
        return physics.Circle(s / 2), s / 2
    return physics.Polygon.regular(rnd.randint(3, 8), s / 2), s / 2


def add_bodies(rnd, w, overlapping: bool):
    """1-6 dynamic bodies on a row (apart, or heaped when ``overlapping``); a static ground half the time."""
    bodies, x = [], 0.0
    for _ in range(rnd.randint(1, 6)):
        shp, r = shape(rnd)
        speed = log_uniform(rnd, SPEED)
        ang = rnd.uniform(0, 2 * math.pi)
        pos = (rnd.uniform(-0.2, 0.2), rnd.uniform(-0.2, 0.2)) if overlapping else (x + r, 2.0 * r + 1.0)
        x += 2.2 * r + 0.1
        bodies.append(w.add_body(shp, position=pos, angle=rnd.uniform(-3, 3),
                                 velocity=(speed * math.cos(ang), speed * math.sin(ang)),
                                 angular_velocity=rnd.uniform(-1, 1) * log_uniform(rnd, (-2.0, 3.0)),
                                 density=log_uniform(rnd, DENSITY), restitution=rnd.choice([0.0, 0.5, 1.0]),
                                 friction=rnd.uniform(0.0, 1.0)))
    if rnd.random() < 0.5:
        bodies.append(w.add_body(physics.Polygon.box(max(20.0, 2 * x), 1.0), position=(x / 2, -0.5),
                                 kind="static"))
    return bodies


def add_springs(rnd, w, bodies):
    """0-3 springs between random dynamic bodies or to world points, k 1..1e9 N/m."""
    dyn = [b for b in bodies if b.kind == "dynamic"]
    for _ in range(rnd.choice([0, 0, 1, 2, 3])):
        a = rnd.choice(dyn)
        others = [b for b in dyn if b is not a]
        b = rnd.choice(others) if others and rnd.random() < 0.6 else None
        r = 0.5 * log_uniform(rnd, SIZE)
        w.add_spring(a, b, anchor_a=(rnd.uniform(-r, r), rnd.uniform(-r, r)),
                     anchor_b=(0.0, 0.0) if b is not None else (rnd.uniform(-3, 3), rnd.uniform(0, 5)),
                     stiffness=log_uniform(rnd, STIFFNESS),
                     damping=0.0 if rnd.random() < 0.5 else log_uniform(rnd, (-2.0, 3.0)),
                     rest_length=None if rnd.random() < 0.5 else rnd.uniform(0.0, 2.0))


JOINT_KINDS = ("revolute", "prismatic", "weld", "distance", "wheel", "motor", "mouse")
DRIVEN = ("motor", "mouse")  # external input: the energy invariant does not apply


def joint_params(rnd, kind: str, a) -> dict:
    """Random parameters of one joint of ``kind`` on body ``a``: limits, springs 0..1e3 Hz, motors."""
    hz = lambda: 0.0 if rnd.random() < 0.5 else log_uniform(rnd, (-1.0, 3.0))  # noqa: E731
    zeta = lambda: rnd.choice([0.0, 0.7, 1.0, 10.0])  # noqa: E731
    x, y = a.position
    if kind == "revolute":
        lo = rnd.uniform(-3, 0) if rnd.random() < 0.5 else None
        return {"anchor": (x + rnd.uniform(-1, 1), y + rnd.uniform(-1, 1)), "lower_angle": lo,
                "upper_angle": None if lo is None else lo + rnd.uniform(0, 3)}
    if kind == "prismatic":
        return {"anchor": (x, y), "axis": (rnd.uniform(-1, 1), 1.0), "lower": -1.0, "upper": rnd.uniform(-1, 2)}
    if kind == "weld":
        return {"anchor": (x, y), "linear_hertz": hz(), "angular_hertz": hz(), "damping_ratio": zeta()}
    if kind == "distance":
        return {"anchor_a": (x, y), "length": rnd.uniform(0.1, 3.0), "spring_hertz": hz(),
                "spring_damping_ratio": zeta()}
    if kind == "wheel":
        return {"anchor": (x, y), "spring_hertz": hz(), "spring_damping_ratio": zeta()}
    if kind == "rotary":
        lo = rnd.uniform(-3, 0) if rnd.random() < 0.5 else None
        return {"lower_angle": lo, "upper_angle": None if lo is None else lo + rnd.uniform(0, 3),
                "spring_hertz": hz(), "spring_damping_ratio": zeta()}
    if kind == "motor":
        return {"max_force": log_uniform(rnd, (0.0, 6.0)), "max_torque": log_uniform(rnd, (0.0, 6.0)),
                "angular_offset": rnd.uniform(-3, 3)}
    return {"target": (x + rnd.uniform(-2, 2), y + rnd.uniform(-2, 2)), "hertz": hz(),
            "max_force": log_uniform(rnd, (0.0, 6.0))}


def add_joints(rnd, w, bodies, plan) -> None:
    """0-2 joints of any kind (world.add_joint) between random dynamic bodies or to the world;
    a third of them breakable.  Motor and mouse joints mark the plan as driven."""
    dyn = [b for b in bodies if b.kind == "dynamic"]
    for _ in range(rnd.choice([0, 0, 0, 1, 2])):
        kind = rnd.choice(JOINT_KINDS)
        a = rnd.choice(dyn)
        others = [b for b in dyn if b is not a]
        b = None if kind == "mouse" or not others or rnd.random() < 0.4 else rnd.choice(others)
        if kind == "motor" and b is None:
            kind = "revolute"
        extra = {"break_force": log_uniform(rnd, (0.0, 6.0))} if rnd.random() < 0.3 else {}
        w.add_joint(kind, a, b, **joint_params(rnd, kind, a), **extra)
        plan.driven = plan.driven or kind in DRIVEN
    add_rotary(rnd, w, dyn)


def add_rotary(rnd, w, dyn) -> None:
    """In about one case in six, a rotary joint (angle limits, an angular spring to 1e3 Hz):
    drawn from a stream of its own, seeded by the case's stream without advancing it, so every
    other draw of every case is what it was before the kind existed (the cases the tests name
    by number are the same worlds)."""
    state = rnd.getstate()[1]
    sub = random.Random(f"rotary:{state[0]}:{state[state[-1] % 624]}:{state[-1]}")
    if not dyn or sub.random() >= 1 / 6:
        return
    a = sub.choice(dyn)
    others = [b for b in dyn if b is not a]
    b = sub.choice(others) if others and sub.random() < 0.6 else None
    w.add_joint("rotary", a, b, **joint_params(sub, "rotary", a))


def build(rnd) -> Plan:
    """A random world in a random mode (gravity on or off) with springs and joints, and its plan
    (5-30 steps, half the cases switching mode mid-run)."""
    modes = physics.solvers_available()
    w = physics.World(gravity=rnd.choice([(0.0, 0.0), (0.0, -9.81)]), solver=rnd.choice(modes),
                      dt=log_uniform(rnd, DT), sleeping=rnd.random() < 0.5)
    overlapping = rnd.random() < 0.2
    bodies = add_bodies(rnd, w, overlapping)
    add_springs(rnd, w, bodies)
    steps = rnd.randint(5, 30)
    plan = Plan(w, steps, overlapping=overlapping)
    add_joints(rnd, w, bodies, plan)
    if rnd.random() < 0.5:
        plan.switch_at = rnd.randrange(steps)
        plan.switch_to = rnd.choice(modes)
    return plan
