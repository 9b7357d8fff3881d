"""Pieces every extreme scenario uses: the world, a ground, energy, extents, and a step loop
that reports a refused step instead of raising it."""
from __future__ import annotations

import numpy as np

from physics import Polygon, SimulationError, World


def world(solver: str, gravity=(0.0, -9.81), settings: dict | None = None, **kw) -> World:
    """A world in ``solver`` with that mode's defaults overridden by ``settings``."""
    return World(gravity=gravity, solver=solver, settings=settings, **kw)


def ground(w: World, width=200.0, top=0.0, x=0.0, thickness=1.0):
    """A static box ``width`` x ``thickness`` m whose top face is at height ``top``."""
    return w.add_body(Polygon.box(width, thickness), kind="static", position=(x, top - 0.5 * thickness),
                      name="ground")


def all_finite(w: World) -> bool:
    """Every body's pose and velocity finite (``world.state()``)."""
    s = w.state()
    return bool(all(np.all(np.isfinite(s[f])) for f in ("position", "angle", "velocity", "angular_velocity")))


def lowest_y(b) -> float:
    """Lowest point of a body's shape (m)."""
    v = b.world_vertices()
    if len(v):
        return float(v[:, 1].min())
    return b.center_of_mass[1] - b.shape.radius


def highest_y(b) -> float:
    """Highest point of a body's shape (m)."""
    v = b.world_vertices()
    if len(v):
        return float(v[:, 1].max())
    return b.center_of_mass[1] + b.shape.radius


def total_energy(w: World) -> float:
    """Kinetic plus potential (gravity and springs) energy (J)."""
    return w.kinetic_energy() + w.potential_energy()


def run_steps(w: World, steps: int, each=None):
    """Step ``steps`` times, calling ``each(k)`` after step k; returns (steps done,
    SimulationError or None): a refused step ends the run and is returned, not raised."""
    for k in range(steps):
        try:
            w.step()
        except SimulationError as exc:
            return k, exc
        if each is not None:
            each(k)
    return steps, None


def refused(exc: SimulationError, k: int, **metrics) -> dict:
    """The metrics of a run that ended with ``exc`` at step ``k``: ``error`` (the message),
    ``error_step``, ``stage``, ``bodies`` (the bodies the error names) and ``metrics``."""
    return dict(error=str(exc), error_step=k, stage=exc.stage, bodies=list(exc.bodies), **metrics)
