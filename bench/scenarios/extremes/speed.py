"""Extreme speed: bodies at 1000 m/s against a 1 cm wall, alone and as a volley."""
from __future__ import annotations

import math

import numpy as np

from physics import Circle, Polygon

from .common import all_finite, refused, run_steps, world

WALL_X, WALL_T = 20.0, 0.01


def _shots():
    """(shape, angle rad, restitution) of the seven shots, each fired from two phases."""
    return [(Polygon.box(0.25, 0.25), 0.0, 0.0), (Polygon.box(0.25, 0.25), math.pi / 4, 0.0),
            (Polygon.box(0.25, 0.25), 0.3, 1.0), (Circle(0.1), 0.0, 0.0), (Circle(0.1), 0.0, 1.0),
            (Polygon.box(1.0, 0.005), 0.0, 0.0), (Polygon.regular(5, 0.15), 0.1, 0.5)]


def build_bullets(solver: str, speed: float = 1000.0, spacing: float = 40.0):
    """(world, {"shots"}): the wall at x = 20 m and 14 shots flying at it, ``spacing`` m apart."""
    w = world(solver, gravity=(0.0, 0.0))
    shots = []
    height = 14 * spacing + 20.0
    w.add_body(Polygon.box(WALL_T, height), kind="static", position=(WALL_X, 0.5 * height - 10.0), name="wall")
    y = 0.0
    for shape, ang, e in _shots():
        for x0 in (0.0, 3.3):  # two phases of the 16.7 m stride against the wall
            b = w.add_body(shape, position=(x0, y), angle=ang, velocity=(speed, 0.0), restitution=e,
                           name=f"shot{len(shots)}")
            shots.append(b)
            y += spacing
    return w, {"shots": shots}


def bullets(solver: str, speed: float = 1000.0, steps: int = 60, spacing: float = 40.0) -> dict:
    """Bodies at 1000 m/s (16.7 m per step) against a 1 cm static wall, no gravity, 40 m
    apart (alone: their swept boxes do not meet).

    Boxes (0.25 m, straight, at 45 degrees and at 0.3 rad with e = 1), discs (r 0.1 m,
    e = 0 and 1), a 1 m x 5 mm sliver flying end-on and a pentagon, each from two
    starting phases against the wall.  Figures: how many end beyond the wall
    (tunnelled) and the largest speed after impact (must not exceed 1000 m/s).
    """
    w, p = build_bullets(solver, speed, spacing)
    shots = p["shots"]
    crossed = set()
    vmax = [0.0]

    def each(k):
        for b in shots:
            if b.center_of_mass[0] > WALL_X:
                crossed.add(b.name)
            vmax[0] = max(vmax[0], float(np.hypot(*b.velocity)))

    k, exc = run_steps(w, steps, each)
    if exc:
        return refused(exc, k)
    return dict(tunnelled=len(crossed), shots=len(shots), max_speed=vmax[0], finite=all_finite(w),
                names=sorted(crossed), speed=speed)


def volley(solver: str, speed: float = 1000.0) -> dict:
    """The same 14 bodies at 1000 m/s, but 3 m apart (a shotgun volley): their swept boxes
    overlap, so the broad phase pairs them with each other as well as with the wall."""
    return bullets(solver, speed, spacing=3.0)
