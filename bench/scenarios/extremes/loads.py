"""Extreme loads: a heavy body on a light one, a spring chain carrying a heavy load, a very
stiff spring.  Each scenario has a builder (the initial world, pinned by the tests) and a
measure (runs it, returns its figures as a dict; a refused step returns ``refused(...)``)."""
from __future__ import annotations

import numpy as np

from physics import Polygon

from .common import all_finite, ground, highest_y, lowest_y, refused, run_steps, total_energy, world


# -- a 1000 kg box on a 1 kg box ----------------------------------------------------------------
def build_mass_ratio_stack(solver: str, settings: dict | None = None):
    """(world, {"light", "heavy"}): the two boxes resting on static ground."""
    w = world(solver, settings=settings)
    ground(w)
    light = w.add_body(Polygon.box(1, 1), position=(0, 0.5), density=1.0, name="light")
    heavy = w.add_body(Polygon.box(1, 1), position=(0, 1.5), density=1000.0, name="heavy")
    return w, {"light": light, "heavy": heavy}


def mass_ratio_stack(solver: str, steps: int = 300, settings: dict | None = None) -> dict:
    """1000 kg box (1 x 1 m) resting on a 1 kg box (1 x 1 m) on static ground, 5 s.

    Figure: the combined sink (light box into the ground + heavy box into the
    light one) over the last second.  Held below 2 cm, degraded below 25 cm.
    """
    w, p = build_mass_ratio_stack(solver, settings)
    light, heavy = p["light"], p["heavy"]
    sinks, speeds = [], []

    def each(k):
        if k >= steps - 60:
            sinks.append(max(0.0, -lowest_y(light)) + max(0.0, highest_y(light) - lowest_y(heavy)))
            speeds.append(max(np.hypot(*light.velocity), np.hypot(*heavy.velocity)))

    k, exc = run_steps(w, steps, each)
    if exc:
        return refused(exc, k)
    return dict(sink=max(sinks), speed=max(speeds), order_kept=heavy.center_of_mass[1] > light.center_of_mass[1],
                finite=all_finite(w))


# -- a spring chain carrying 100 kg ---------------------------------------------------------------
CHAIN_LINKS, CHAIN_K, CHAIN_C, CHAIN_REST = 4, 2.0e4, 400.0, 1.0
CHAIN_TOP = 10.0
CHAIN_MASSES = [1.0] * CHAIN_LINKS + [100.0]


def build_spring_chain(solver: str, settings: dict | None = None):
    """(world, {"bodies"}): four 1 kg links and a 100 kg box hung at rest lengths from (0, 10)."""
    w = world(solver, settings=settings)
    bodies = []
    prev = None
    for i, mass in enumerate(CHAIN_MASSES):
        y = CHAIN_TOP - CHAIN_REST * (i + 1)
        b = w.add_body(Polygon.box(0.5, 0.5), position=(0, y), density=mass / 0.25, name=f"link{i}")
        if prev is None:
            w.add_spring(b, None, anchor_b=(0, CHAIN_TOP), stiffness=CHAIN_K, damping=CHAIN_C, rest_length=CHAIN_REST)
        else:
            w.add_spring(prev, b, stiffness=CHAIN_K, damping=CHAIN_C, rest_length=CHAIN_REST)
        bodies.append(b)
        prev = b
    return w, {"bodies": bodies}


def spring_chain(solver: str, steps: int = 900, settings: dict | None = None) -> dict:
    """A chain of springs (k = 2e4 N/m, c = 400 N s/m) from a world anchor through four
    1 kg boxes to a 100 kg box; released at rest lengths, 15 s.

    Light links between heavy loads are the stiff direction: sqrt(2k/m) dt = 3.3,
    beyond explicit stability.  Figures: the bottom box's rest height against the
    static solution and the largest rise of total energy (damping may only remove it).
    """
    w, p = build_spring_chain(solver, settings)
    bodies = p["bodies"]
    g = 9.81
    masses = CHAIN_MASSES
    # spring i carries everything below it
    stretch = sum(g * sum(masses[i:]) / CHAIN_K for i in range(len(masses)))
    y_static = CHAIN_TOP - CHAIN_REST * len(masses) - stretch
    e0 = total_energy(w)
    rise = [0.0]

    def each(k):
        rise[0] = max(rise[0], total_energy(w) - e0)

    k, exc = run_steps(w, steps, each)
    if exc:
        return refused(exc, k)
    err = abs(bodies[-1].center_of_mass[1] - y_static)
    speed = max(np.hypot(*b.velocity) for b in bodies)
    released = 100 * g * stretch  # scale of the energy the fall releases
    return dict(error=err, stretch=stretch, rel_error=err / stretch, energy_rise=rise[0],
                energy_scale=released, speed=speed, finite=all_finite(w))


# -- a very stiff spring ---------------------------------------------------------------------------
STIFF_K = 1.0e6


def build_stiff_spring(solver: str, integrator: str | None = None):
    """(world, {"bob"}): a 1 kg box on a k = 1e6 N/m spring, stretched 0.1 m, no gravity."""
    kw = {} if integrator is None else {"integrator": integrator}
    w = world(solver, gravity=(0.0, 0.0), **kw)
    b = w.add_body(Polygon.box(1, 1), position=(1.1, 0.0), density=1.0, name="bob")
    w.add_spring(b, None, anchor_b=(0.0, 0.0), stiffness=STIFF_K, damping=0.0, rest_length=1.0)
    return w, {"bob": b}


def stiff_spring(solver: str, steps: int = 600, integrator: str | None = None) -> dict:
    """k = 1e6 N/m on a 1 kg box at dt = 1/60 (k dt^2 / m = 278), no damping, no gravity;
    stretched 0.1 m and released (E0 = 5000 J), 10 s.

    Held: finite and the total energy never exceeds E0 by 1%.  An explicit mode
    may instead refuse the step with SimulationError (degraded: honest); energy
    growth or NaN reaching the user is failed.
    """
    w, _ = build_stiff_spring(solver, integrator)
    e0 = total_energy(w)
    peak = [e0]
    quarter = max(1, steps // 4)
    first, last = [e0], [0.0]  # peak energy in the first and the last quarter of the run

    def each(k):
        e = total_energy(w)
        peak[0] = max(peak[0], e)
        if k < quarter:
            first[0] = max(first[0], e)
        elif k >= steps - quarter:
            last[0] = max(last[0], e)

    k, exc = run_steps(w, steps, each)
    growth = peak[0] / e0
    if exc:
        finite = all_finite(w)
        return refused(exc, k, growth=growth, finite=finite, reverted=finite and w.fault is exc)
    # drift: a symplectic method's energy oscillates (bounded) but must not creep upwards
    return dict(growth=growth, retained=total_energy(w) / e0, drift=last[0] / first[0], finite=all_finite(w))
