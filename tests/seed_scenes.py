"""Scenes with analytic answers shared by the seed-mode tests (not a test module)."""
import math

import numpy as np

import physics
from builders import ground  # noqa: F401 (the seed tests take it from here too)


def world(solver, integrator="symplectic_euler", gravity=(0.0, -9.81), dt=1 / 60, **settings):
    w = physics.World(gravity=gravity, dt=dt, solver=solver, integrator=integrator, sleeping=False)
    for k, v in settings.items():
        w.settings[k] = v
    return w


def box_on(w, angle=0.0, height=0.0, **kw):
    """A 1 x 1 box (1 kg) with its bottom face `height` above the tilted ground's top face."""
    c, s = math.cos(angle), math.sin(angle)
    d = 0.5 + height
    return w.add_body(physics.Polygon.box(1, 1), position=(-d * s, d * c), angle=angle, **kw)


def bounce_height(solver, e, drop=1.0, **settings):
    """Highest bottom-face height after the first impact of a box dropped flat from `drop`."""
    w = world(solver, **settings)
    ground(w)
    b = box_on(w, height=drop, restitution=e)
    hit = False
    best = -1.0
    for _ in range(240):
        w.step()
        y = b.position[1] - 0.5
        if not hit and b.velocity[1] > 0.0:
            hit = True
        if hit:
            best = max(best, y)
            if b.velocity[1] < 0.0 and y < best - 0.02:
                break
    return best, w, b


def slope_run(solver, deg, friction, seconds=3.0, **settings):
    """Distance slid along a slope and the fitted acceleration (after 0.5 s)."""
    th = math.radians(deg)
    w = world(solver, **settings)
    ground(w, angle=th, friction=friction)
    b = box_on(w, th, friction=friction)
    down = np.array([-math.cos(th), -math.sin(th)])
    p0 = np.array(b.position)
    ts, ss = [], []
    for _ in range(int(round(seconds / w.dt))):
        w.step()
        ts.append(w.time)
        ss.append(float((np.array(b.position) - p0) @ down))
    ts, ss = np.array(ts), np.array(ss)
    keep = ts > 0.5
    acc = 2.0 * np.polyfit(ts[keep], ss[keep], 2)[0]
    return ss[-1], acc, b


def resting_range(solver, seconds=10.0, **settings):
    """(max - min) of a resting box's height over `seconds`, and its final speed."""
    w = world(solver, **settings)
    ground(w)
    b = box_on(w)
    ys = []
    for _ in range(int(round(seconds / w.dt))):
        w.step()
        ys.append(b.position[1])
    return max(ys) - min(ys), float(np.hypot(*b.velocity)), max(abs(y - 0.5) for y in ys)
