"""Extreme scale: 1 cm and 100 m boxes, a pyramid 10 km from the origin, 10 000 bodies."""
from __future__ import annotations

import math
import time

import numpy as np

from physics import Polygon

from .common import all_finite, ground, refused, run_steps, total_energy, world


# -- stacks of tiny and huge boxes ---------------------------------------------------------------
def build_scaled_stack(solver: str, size: float, count: int = 5, settings: dict | None = None):
    """(world, {"boxes"}): ``count`` boxes of side ``size`` m stacked touching on static ground."""
    w = world(solver, settings=settings)
    ground(w, width=40 * size, thickness=size)
    boxes = [w.add_body(Polygon.box(size, size), position=(0, size * (i + 0.5)), name=f"b{i}")
             for i in range(count)]
    return w, {"boxes": boxes}


def scaled_stack(solver: str, size: float, count: int = 5, seconds: float = 4.0,
                 settings: dict | None = None) -> dict:
    """``count`` boxes of side ``size`` stacked on static ground (placed touching), 4 s.

    Figures relative to the box size: the top box's height error (sink) and the
    largest sideways drift.  Held below 10%, degraded below 50% (still a stack).
    """
    w, p = build_scaled_stack(solver, size, count, settings)
    boxes = p["boxes"]
    k, exc = run_steps(w, int(round(seconds / w.dt)))
    if exc:
        return refused(exc, k)
    top = boxes[-1]
    sink = abs(top.center_of_mass[1] - size * (count - 0.5)) / size
    drift = max(abs(b.center_of_mass[0]) for b in boxes) / size
    tilt = max(abs(math.remainder(b.angle, math.pi / 2)) for b in boxes)
    return dict(sink=sink, drift=drift, tilt=tilt, finite=all_finite(w))


def small_stack(solver, **kw) -> dict:
    """Five 0.01 m boxes stacked (see ``scaled_stack``)."""
    return scaled_stack(solver, 0.01, **kw)


def large_stack(solver, **kw) -> dict:
    """Five 100 m boxes stacked (see ``scaled_stack``)."""
    return scaled_stack(solver, 100.0, **kw)


# -- far from the origin -------------------------------------------------------------------------
FAR = (6000.0, 8000.0)  # 10 km from the origin


def pyramid(w, rows: int, origin=(0.0, 0.0), size=1.0) -> list:
    """A box pyramid of ``rows`` rows (side ``size`` m) on its own ground at ``origin``; the boxes."""
    ox, oy = origin
    ground(w, width=4 * rows * size, x=ox, top=oy)
    out = []
    for r in range(rows):
        for c in range(rows - r):
            x = ox + (c - 0.5 * (rows - r - 1)) * size * 1.0
            y = oy + (r + 0.5) * size
            out.append(w.add_body(Polygon.box(size, size), position=(x, y)))
    return out


def build_far_pyramid(solver: str, rows: int = 10, origin=(0.0, 0.0)):
    """(world, {"boxes"}): one pyramid of ``rows`` rows at ``origin``."""
    w = world(solver)
    return w, {"boxes": pyramid(w, rows, origin)}


def far_pyramid(solver: str, rows: int = 10, steps: int = 300) -> dict:
    """A 10-row box pyramid (55 boxes) at the origin and the same one 10 km away
    (6000, 8000), 5 s each.  Figures: the largest difference between the two
    (relative positions) and the largest drift of the far one from its layout.
    Held when they differ by < 1 cm and the far one drifts < 5 cm.
    """
    runs = []
    for origin in ((0.0, 0.0), FAR):
        w, p = build_far_pyramid(solver, rows, origin)
        boxes = p["boxes"]
        start = np.array([b.center_of_mass for b in boxes])
        k, exc = run_steps(w, steps)
        if exc:
            return refused(exc, k)
        end = np.array([b.center_of_mass for b in boxes])
        runs.append((start - np.array(origin), end - np.array(origin)))
    diff = float(np.max(np.abs(runs[0][1] - runs[1][1])))
    drift_far = float(np.max(np.hypot(*(runs[1][1] - runs[1][0]).T)))
    drift_origin = float(np.max(np.hypot(*(runs[0][1] - runs[0][0]).T)))
    return dict(difference=diff, drift_far=drift_far, drift_origin=drift_origin,
                finite=bool(np.all(np.isfinite(runs[1][1]))))


# -- many bodies -----------------------------------------------------------------------------------
def build_ten_thousand(solver: str, count: int = 10_000):
    """(world, {"boxes"}): ``count`` 0.4 m boxes in a grid 200 wide, 5 cm above static ground."""
    w = world(solver)
    cols = 200
    rows = count // cols
    ground(w, width=cols * 0.5 + 20)
    boxes = []
    for r in range(rows):
        for c in range(cols):
            boxes.append(w.add_body(Polygon.box(0.4, 0.4), position=((c - cols / 2) * 0.5, 0.25 + r * 0.5)))
    return w, {"boxes": boxes}


def ten_thousand(solver: str, steps: int = 120, count: int = 10_000) -> dict:
    """10 000 boxes (0.4 m) in a 200 x 50 grid dropped 5 cm onto static ground, 2 s.

    Figures: ms per step, bodies below the ground (tunnelled), energy rise over the
    initial total.  Held: finite, nothing through the ground, no energy gained.
    """
    w, p = build_ten_thousand(solver, count)
    e0 = total_energy(w)
    t0 = time.perf_counter()
    k, exc = run_steps(w, steps)
    ms = 1000 * (time.perf_counter() - t0) / max(k, 1)
    if exc:
        return refused(exc, k, ms_per_step=ms)
    below = int(sum(b.center_of_mass[1] < 0.0 for b in p["boxes"]))
    return dict(ms_per_step=ms, below=below, energy_rise=total_energy(w) - e0, e0=e0, finite=all_finite(w))
