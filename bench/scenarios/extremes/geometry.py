"""Degenerate geometry: near-collinear vertices, 1:1000 slivers, coincident bodies."""
from __future__ import annotations

import math

import numpy as np

from physics import Polygon

from .common import all_finite, ground, highest_y, lowest_y, refused, run_steps, total_energy, world

NEAR_COLLINEAR = Polygon([(-0.5, -0.5), (0.0, -0.5 - 1e-7), (0.5, -0.5), (0.5, 0.5), (0.0, 0.5 + 1e-7),
                          (-0.5, 0.5)])


def build_near_collinear(solver: str):
    """(world, {"bodies"}): three near-collinear boxes, tilted, stacked above static ground."""
    w = world(solver)
    ground(w)
    bs = [w.add_body(NEAR_COLLINEAR, position=(0.1 * i, 0.55 + 1.05 * i), angle=0.02 * (i - 1), name=f"p{i}")
          for i in range(3)]
    return w, {"bodies": bs}


def near_collinear(solver: str, steps: int = 480) -> dict:
    """Boxes with an extra vertex 1e-7 m off the middle of the top and bottom edges
    (a 2e-7 rad turn), dropped tilted onto ground and stacked three high, 8 s (plain boxes
    rest after 4 s; these still rock at 0.07 m/s then).

    Figures: sink into the ground / each other and the largest speed at the end.
    Held: rests (speed < 0.05 m/s) with sink < 2 cm.
    """
    w, p = build_near_collinear(solver)
    bs = p["bodies"]
    k, exc = run_steps(w, steps)
    if exc:
        return refused(exc, k)
    sink = max(0.0, -lowest_y(bs[0]))
    for lo, hi in zip(bs, bs[1:]):
        sink = max(sink, highest_y(lo) - lowest_y(hi))
    speed = max(np.hypot(*b.velocity) for b in bs)
    upright = all(b.center_of_mass[1] > a.center_of_mass[1] + 0.5 for a, b in zip(bs, bs[1:]))
    return dict(sink=sink, speed=speed, upright=upright, finite=all_finite(w))


def build_slivers(solver: str):
    """(world, {"bodies"}): three 1 m x 1 mm slivers falling (flat, tilted, end-on) and three stacked."""
    w = world(solver)
    ground(w)
    sl = Polygon.box(1.0, 0.001)
    bs = [w.add_body(sl, position=(-3, 0.3), name="flat"),
          w.add_body(sl, position=(0, 1.0), angle=math.pi / 6, name="tilted"),
          w.add_body(sl, position=(3, 1.0), angle=math.pi / 2, velocity=(0, -10), name="end-on")]
    for i in range(3):
        bs.append(w.add_body(sl, position=(6 + 0.01 * i, 0.0005 + 0.001 * i + 0.0001 * i), name=f"stack{i}"))
    return w, {"bodies": bs}


def slivers(solver: str, steps: int = 300) -> dict:
    """Slivers 1 m x 1 mm (aspect 1:1000): one dropped flat, one at 30 degrees, one
    falling end-first at 10 m/s, then three more stacked flat; 5 s.

    Figures: the deepest point below the ground surface (tunnelling if < -1 mm
    thickness... held when nothing goes below -5 mm), energy rise, rest speed.
    """
    w, p = build_slivers(solver)
    bs = p["bodies"]
    e0 = total_energy(w)
    rise = [0.0]
    deepest = [0.0]

    def each(k):
        rise[0] = max(rise[0], total_energy(w) - e0)
        deepest[0] = min(deepest[0], min(lowest_y(b) for b in bs))

    k, exc = run_steps(w, steps, each)
    if exc:
        return refused(exc, k)
    speed = max(np.hypot(*b.velocity) for b in bs)
    return dict(deepest=deepest[0], energy_rise=rise[0], speed=speed, finite=all_finite(w))


def build_coincident(solver: str, count: int = 8):
    """(world, {"bodies"}): ``count`` 1 m boxes at the same place, no gravity."""
    w = world(solver, gravity=(0.0, 0.0))
    bs = [w.add_body(Polygon.box(1, 1), position=(0.0, 0.0), name=f"c{i}") for i in range(count)]
    return w, {"bodies": bs}


def coincident(solver: str, count: int = 8, steps: int = 300) -> dict:
    """Eight 1 m boxes created exactly on top of each other (no gravity), 5 s.

    Figures: the largest body speed while separating (the push-out must be
    capped: held below 10 m/s, failed above 100 m/s = an explosion), the deepest
    remaining overlap, and linear momentum (starts at zero).
    """
    w, p = build_coincident(solver, count)
    bs = p["bodies"]
    vmax = [0.0]

    def each(k):
        vmax[0] = max(vmax[0], max(float(np.hypot(*b.velocity)) for b in bs))

    k, exc = run_steps(w, steps, each)
    if exc:
        return refused(exc, k)
    depth = max([c.depth for c in w.contacts()] + [0.0])
    mom = float(np.hypot(*w.linear_momentum()))
    return dict(max_speed=vmax[0], depth=depth, momentum=mom, finite=all_finite(w))
