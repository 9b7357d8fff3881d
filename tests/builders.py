"""Scene builders shared by the tests (not a test module): worlds, grounds, pyramids, stacks,
rain, containers, and reads of the state through the public API (``world.state()``).

Every builder adds bodies to a world it is given and returns their handles, so a test states
the world it wants in one line and the same ground or pyramid is written once.
"""
from __future__ import annotations

import hashlib
import math

import numpy as np

import physics

G = (0.0, -10.0)
DT = 1 / 60


def world(solver="soft_step", gravity=G, dt=DT, sleeping=False, settings=None, **kw) -> physics.World:
    """A world in ``solver`` (gravity m/s^2, dt s; sleeping off unless asked)."""
    return physics.World(gravity=gravity, dt=dt, solver=solver, sleeping=sleeping, settings=settings, **kw)


def ground(w, width=40.0, angle=0.0, friction=0.6, name="ground", x=0.0):
    """A static ``width`` x 1 m box whose top face passes through (``x``, 0), tilted by ``angle`` rad
    about that point."""
    c, s = math.cos(angle), math.sin(angle)
    return w.add_body(physics.Polygon.box(width, 1), kind="static", position=(x + 0.5 * s, -0.5 * c),
                      angle=angle, friction=friction, name=name)


def wall(w, x, height, y0=0.0, thickness=1.0, friction=0.6, name=None):
    """A static vertical ``thickness`` x ``height`` m box centred on ``x``, standing on ``y0``."""
    return w.add_body(physics.Polygon.box(thickness, height), kind="static", position=(x, y0 + 0.5 * height),
                      friction=friction, name=name)


def pyramid(w, base, friction=0.6, size=1.0) -> list:
    """The standard pyramid on the ground's top face: row i has ``base - i`` boxes of side
    ``size`` m, centred on x = 0, at y = (i + 1/2) size.  Returns the boxes, bottom row first."""
    out = []
    for i in range(base):
        for j in range(base - i):
            out.append(w.add_body(physics.Polygon.box(size, size),
                                  position=((j - (base - i - 1) / 2.0) * size, (0.5 + i) * size), friction=friction))
    return out


def pyramid_world(base, solver="soft_step", settings=None):
    """(world, top box): the pyramid of ``base`` on a ground 2 base + 20 m wide, gravity -10,
    dt 1/60, sleeping off, friction 0.6 (the stacking figures of docs/benchmarks.md)."""
    w = world(solver, settings=settings)
    ground(w, width=2 * base + 20, name=None)
    return w, pyramid(w, base)[-1]


def stack(w, n=3, x=0.0, size=1.0, **kw) -> list:
    """``n`` boxes of side ``size`` m stacked touching on the ground's top face at ``x``."""
    return [w.add_body(physics.Polygon.box(size, size), position=(x, size * (0.5 + i)), **kw) for i in range(n)]


def container(w, width, height, floor_width=None, friction=0.6, names=(None, None, None)):
    """An open box: a floor (top face at 0) and two walls of ``height`` m, ``width`` m apart inside."""
    floor = ground(w, width=floor_width if floor_width is not None else width + 2, friction=friction, name=names[0])
    left = wall(w, -0.5 * width - 0.5, height, friction=friction, name=names[1])
    right = wall(w, 0.5 * width + 0.5, height, friction=friction, name=names[2])
    return floor, left, right


def rain_sizes(count=1000, seed=3):
    """Box sizes (count, 2), x jitter and spin of the stacking test's rain, from one seeded stream."""
    rng = np.random.default_rng(seed)
    return rng.uniform(0.4, 1.2, size=(count, 2)), rng.uniform(-0.2, 0.2, size=count), rng.uniform(-1, 1, size=count)


def rain(w, sizes, jitter, spin, per_row=25, every=12, height=34.0):
    """Generator: steps ``w``, adding a row of ``per_row`` boxes every ``every`` steps at ``height``
    (falling at 5 m/s) until all are in; yields the boxes added so far after each step."""
    added = []
    k = 0
    while len(added) < len(sizes):
        if k % every == 0:
            for c in range(per_row):
                i = len(added)
                if i >= len(sizes):
                    break
                x = -18.5 + 37.0 * c / (per_row - 1) + jitter[i]
                added.append(w.add_body(physics.Polygon.box(*sizes[i]), position=(x, height), angle=spin[i],
                                        velocity=(0.0, -5.0), friction=0.6))
        w.step()
        k += 1
        yield added


# -- reading the state (public API) ------------------------------------------------------------------
def state_array(w) -> np.ndarray:
    """(n, 6) float array of every body's x, y (origin), angle, vx, vy, angular velocity."""
    s = w.state()
    return np.column_stack([s["position"], s["angle"], s["velocity"], s["angular_velocity"]])


def finite(w) -> bool:
    """Every body's pose and velocity finite."""
    return bool(np.all(np.isfinite(state_array(w))))


def positions(w) -> np.ndarray:
    """(n, 2) body origins (a copy)."""
    return np.array(w.state()["position"])


def speeds(w) -> np.ndarray:
    """(n,) linear speed of every body (m/s)."""
    return np.hypot(*w.state()["velocity"].T)


def state_digest(w) -> str:
    """SHA-256 of every body's pose, velocity and awake flag (as stored, bit for bit)."""
    s = w.state()
    h = hashlib.sha256()
    for f in ("position", "angle", "velocity", "angular_velocity", "awake"):
        h.update(np.ascontiguousarray(s[f]).tobytes())
    return h.hexdigest()
