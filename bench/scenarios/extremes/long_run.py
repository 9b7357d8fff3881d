"""A long run: 100 000 steps of a reduced tumbler (a driven drum of kinematic walls)."""
from __future__ import annotations

import math
import time

import numpy as np

from physics import Circle, Polygon, SimulationError

from .common import all_finite, refused, world

TUMBLER_R, TUMBLER_W = 3.0, 0.5  # drum radius (m), angular speed (rad/s)


class Drum:
    """The tumbler's drum: ``walls`` (kinematic bodies) placed on the circle by ``drive``."""

    def __init__(self, walls):
        self.walls = walls

    def place(self, phase: float) -> None:
        """Walls (pose and velocity) where the drum is at angle ``phase`` (rad)."""
        sides = len(self.walls)
        r = TUMBLER_R + 0.15
        for i, b in enumerate(self.walls):
            a = phase + 2 * math.pi * i / sides
            c = (r * math.sin(a), -r * math.cos(a))
            b.angle = a
            b.position = c
            b.velocity = (TUMBLER_W * r * math.cos(a), TUMBLER_W * r * math.sin(a))
            b.angular_velocity = TUMBLER_W

    def drive(self, w) -> None:
        """Put the drum walls where the drive says at the world's current time (no drift)."""
        self.place(TUMBLER_W * w.time)


def build_tumbler(solver: str, sides: int = 12, shapes: int = 24):
    """(world, {"drum", "inside"}): a 12-sided drum (radius 3 m) of kinematic wall boxes with 24
    mixed bodies inside (boxes, discs, pentagons; e = 0.2)."""
    w = world(solver)
    walls = []
    for i in range(sides):
        walls.append(w.add_body(Polygon.box(2 * TUMBLER_R * math.tan(math.pi / sides) + 0.2, 0.3),
                                kind="kinematic", name=f"wall{i}"))
    rng = np.random.default_rng(7)
    inside = []
    for i in range(shapes):
        x = -1.5 + (i % 6) * 0.6
        y = -1.2 + (i // 6) * 0.6
        kind = i % 3
        shape = (Polygon.box(0.4, 0.3) if kind == 0 else Circle(0.2) if kind == 1
                 else Polygon.regular(5, 0.22))
        inside.append(w.add_body(shape, position=(x, y), angle=float(rng.uniform(0, 1)), restitution=0.2,
                                 name=f"s{i}"))
    drum = Drum(walls)
    drum.place(0.0)
    return w, {"drum": drum, "inside": inside}


def _contents_energy(inside) -> float:
    e = 0.0
    for b in inside:
        v = b.velocity
        e += 0.5 * b.mass * (v[0] ** 2 + v[1] ** 2) + 0.5 * b.inertia * b.angular_velocity ** 2 \
            + b.mass * 9.81 * b.center_of_mass[1]
    return e


def long_run(solver: str, steps: int = 100_000, check_every: int = 100) -> dict:
    """100 000 steps (27.8 min simulated) of the reduced tumbler.

    Figures: the largest total energy of the contents (kinetic + potential about the
    drum centre) in the last tenth of the run against the first tenth, and how
    many bodies left the drum.  Held: finite, none escaped, late energy at most
    1.5x early energy (no secular growth).
    """
    w, p = build_tumbler(solver)
    drum, inside = p["drum"], p["inside"]
    energies = []
    escaped = set()
    t0 = time.perf_counter()
    for k in range(steps):
        drum.drive(w)
        try:
            w.step()
        except SimulationError as exc:
            return refused(exc, k)
        if k % check_every == 0:
            energies.append(_contents_energy(inside))
            escaped |= {b.name for b in inside if np.hypot(*b.center_of_mass) > TUMBLER_R + 0.5}
    secs = time.perf_counter() - t0
    e = np.array(energies)
    tenth = max(1, len(e) // 10)
    floor = -sum(b.mass for b in inside) * 9.81 * TUMBLER_R  # all at the drum bottom
    early = e[:tenth].max() - floor
    late = e[-tenth:].max() - floor
    peak = e.max() - floor
    return dict(early=early, late=late, ratio=late / early, peak_ratio=peak / early, escaped=len(escaped),
                seconds=secs, steps=steps, finite=bool(np.all(np.isfinite(e))) and all_finite(w))
