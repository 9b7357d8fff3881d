"""Reliability at the extremes: every probe in every solver mode -> docs/reliability.md.

    python -m bench.reliability [--quick] [--modes soft_step,sequential_impulse] [--out PATH]

Each probe builds one extreme scene (mass ratio, stiff spring, speed, scale,
degenerate geometry, long run), runs it in one solver mode with that mode's
default settings and measures one figure.  The outcome is

- **held**: the claim of the regime holds (finite, bounded energy, no
  tunnelling, drift below the stated bound);
- **degraded**: the world stayed finite and honest but the claim holds only
  approximately (e.g. sinks or drifts beyond the bound but less than a body
  size), or the step was refused with a clear ``SimulationError`` where that
  is an acceptable answer (stiff springs in an explicit mode);
- **failed**: tunnelling, energy growth, non-finite values, an unexplained
  ``SimulationError``, or a claim missed by more than a body size.

The tests in ``tests/extremes/`` call the same probe functions and assert
their figures, so the table and the suite measure the same thing.
"""
from __future__ import annotations

import argparse
import math
import platform
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

import physics
from physics import Circle, Polygon, SimulationError, World

DOC = Path(__file__).resolve().parent.parent / "docs" / "reliability.md"
HELD, DEGRADED, FAILED, UNAVAILABLE = "held", "degraded", "failed", "n/a"


@dataclass
class Outcome:
    status: str
    figure: str
    metrics: dict = field(default_factory=dict)
    seconds: float = 0.0

    def __str__(self):
        return f"{self.status}: {self.figure}"


def world(solver: str, gravity=(0.0, -9.81), settings: dict | None = None, **kw) -> World:
    return World(gravity=gravity, solver=solver, settings=settings, **kw)


def ground(w: World, width=200.0, top=0.0, x=0.0, thickness=1.0):
    return w.add_body(Polygon.box(width, thickness), kind="static", position=(x, top - 0.5 * thickness),
                      name="ground")


def dynamic_state(w: World) -> np.ndarray:
    """(n, 6) array of x, y, angle, vx, vy, w of every body (slot order)."""
    n = w._bodies.n
    B = w._bodies.view
    return np.column_stack([B.x[:n], B.q[:n], B.v[:n], B.w[:n]])


def all_finite(w: World) -> bool:
    return bool(np.all(np.isfinite(dynamic_state(w))))


def lowest_y(b) -> float:
    v = b.world_vertices()
    if len(v):
        return float(v[:, 1].min())
    return b.center_of_mass[1] - b.shape.radius


def highest_y(b) -> float:
    v = b.world_vertices()
    if len(v):
        return float(v[:, 1].max())
    return b.center_of_mass[1] + b.shape.radius


def total_energy(w: World) -> float:
    return w.kinetic_energy() + w.potential_energy()


def run_steps(w: World, steps: int, each=None):
    """Step ``steps`` times; returns (steps done, SimulationError or None)."""
    for k in range(steps):
        try:
            w.step()
        except SimulationError as exc:
            return k, exc
        if each is not None:
            each(k)
    return steps, None


def _err_outcome(exc: SimulationError, k: int, status=FAILED, **metrics) -> Outcome:
    return Outcome(status, f"SimulationError at step {k} ({exc.stage}: {', '.join(exc.bodies[:3])})",
                   dict(error=str(exc), error_step=k, stage=exc.stage, **metrics))


# ---------------------------------------------------------------------------
# mass ratios
# ---------------------------------------------------------------------------
def mass_ratio_stack(solver: str, steps: int = 300, settings: dict | None = None) -> Outcome:
    """1000 kg box (1 x 1 m) resting on a 1 kg box (1 x 1 m) on static ground, 5 s.

    Figure: the combined sink (light box into the ground + heavy box into the
    light one) over the last second.  Held below 2 cm, degraded below 25 cm.
    """
    w = world(solver, settings=settings)
    ground(w)
    light = w.add_body(Polygon.box(1, 1), position=(0, 0.5), density=1.0, name="light")
    heavy = w.add_body(Polygon.box(1, 1), position=(0, 1.5), density=1000.0, name="heavy")
    sinks, speeds = [], []

    def each(k):
        if k >= steps - 60:
            sinks.append(max(0.0, -lowest_y(light)) + max(0.0, highest_y(light) - lowest_y(heavy)))
            speeds.append(max(np.hypot(*light.velocity), np.hypot(*heavy.velocity)))

    k, exc = run_steps(w, steps, each)
    if exc:
        return _err_outcome(exc, k)
    sink = max(sinks)
    order_kept = heavy.center_of_mass[1] > light.center_of_mass[1]
    m = dict(sink=sink, speed=max(speeds), order_kept=order_kept, finite=all_finite(w))
    fig = f"sink {sink * 1000:.1f} mm, speed {max(speeds):.2g} m/s"
    if not order_kept or not m["finite"]:
        return Outcome(FAILED, "heavy box passed through the light one", m)
    if sink < 0.02 and max(speeds) < 0.05:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if sink < 0.25 else FAILED, fig, m)


CHAIN_LINKS, CHAIN_K, CHAIN_C, CHAIN_REST = 4, 2.0e4, 400.0, 1.0


def spring_chain(solver: str, steps: int = 900, settings: dict | None = None) -> Outcome:
    """A chain of springs (k = 2e4 N/m, c = 400 N s/m) from a world anchor through four
    1 kg boxes to a 100 kg box; released at rest lengths, 15 s.

    Light links between heavy loads are the stiff direction: sqrt(2k/m) dt = 3.3,
    beyond explicit stability.  Figures: the bottom box's rest height against the
    static solution and the largest rise of total energy (damping may only remove it).
    """
    w = world(solver, settings=settings)
    top = 10.0
    bodies = []
    prev = None
    masses = [1.0] * CHAIN_LINKS + [100.0]
    for i, mass in enumerate(masses):
        y = top - CHAIN_REST * (i + 1)
        b = w.add_body(Polygon.box(0.5, 0.5), position=(0, y), density=mass / 0.25, name=f"link{i}")
        if prev is None:
            w.add_spring(b, None, anchor_b=(0, top), stiffness=CHAIN_K, damping=CHAIN_C, rest_length=CHAIN_REST)
        else:
            w.add_spring(prev, b, stiffness=CHAIN_K, damping=CHAIN_C, rest_length=CHAIN_REST)
        bodies.append(b)
        prev = b
    g = 9.81
    # spring i carries everything below it
    stretch = sum(g * sum(masses[i:]) / CHAIN_K for i in range(len(masses)))
    y_static = top - CHAIN_REST * len(masses) - stretch
    e0 = total_energy(w)
    rise = [0.0]

    def each(k):
        rise[0] = max(rise[0], total_energy(w) - e0)

    k, exc = run_steps(w, steps, each)
    if exc:
        return _err_outcome(exc, k)
    bottom = bodies[-1]
    err = abs(bottom.center_of_mass[1] - y_static)
    speed = max(np.hypot(*b.velocity) for b in bodies)
    released = 100 * g * stretch  # scale of the energy the fall releases
    m = dict(error=err, stretch=stretch, rel_error=err / stretch, energy_rise=rise[0],
             energy_scale=released, speed=speed, finite=all_finite(w))
    fig = f"rest error {100 * err / stretch:.1f}% of stretch, energy rise {rise[0]:.2g} J"
    if not m["finite"] or rise[0] > 0.01 * released:
        return Outcome(FAILED, fig, m)
    if err < 0.05 * stretch and speed < 0.01:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if err < 0.5 else FAILED, fig, m)


# ---------------------------------------------------------------------------
# stiff springs
# ---------------------------------------------------------------------------
STIFF_K = 1.0e6


def stiff_spring(solver: str, steps: int = 600, integrator: str | None = None) -> Outcome:
    """k = 1e6 N/m on a 1 kg box at dt = 1/60 (k dt^2 / m = 278), no damping, no gravity;
    stretched 0.1 m and released (E0 = 5000 J), 10 s.

    Held: finite and the total energy never exceeds E0 by 1%.  An explicit mode
    may instead refuse the step with SimulationError (degraded: honest); energy
    growth or NaN reaching the user is failed.
    """
    kw = {} if integrator is None else {"integrator": integrator}
    w = world(solver, gravity=(0.0, 0.0), **kw)
    b = w.add_body(Polygon.box(1, 1), position=(1.1, 0.0), density=1.0, name="bob")
    w.add_spring(b, None, anchor_b=(0.0, 0.0), stiffness=STIFF_K, damping=0.0, rest_length=1.0)
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
        reverted_ok = all_finite(w) and w.fault is exc
        st = DEGRADED if reverted_ok and growth <= 1.01 else FAILED
        out = _err_outcome(exc, k, st, growth=growth, finite=all_finite(w), reverted=reverted_ok)
        if st == FAILED and reverted_ok:
            out.figure = f"energy grew x{growth:.3g} before SimulationError at step {k}"
        return out
    e_end = total_energy(w)
    # drift: a symplectic method's energy oscillates (bounded) but must not creep upwards
    drift = last[0] / first[0]
    m = dict(growth=growth, retained=e_end / e0, drift=drift, finite=all_finite(w))
    fig = f"peak energy x{growth:.4g}, after 10 s x{e_end / e0:.2g}, drift x{drift:.4g}"
    if not m["finite"]:
        return Outcome(FAILED, fig, m)
    if growth <= 1.01:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if drift <= 1.01 else FAILED, fig, m)


# ---------------------------------------------------------------------------
# speed
# ---------------------------------------------------------------------------
WALL_X, WALL_T = 20.0, 0.01


def bullets(solver: str, speed: float = 1000.0, steps: int = 60, spacing: float = 40.0) -> Outcome:
    """Bodies at 1000 m/s (16.7 m per step) against a 1 cm static wall, no gravity, 40 m
    apart (alone: their swept boxes do not meet).

    Boxes (0.25 m, straight, at 45 degrees and at 0.3 rad with e = 1), discs (r 0.1 m,
    e = 0 and 1), a 1 m x 5 mm sliver flying end-on and a pentagon, each from two
    starting phases against the wall.  Figures: how many end beyond the wall
    (tunnelled) and the largest speed after impact (must not exceed 1000 m/s).
    """
    w = world(solver, gravity=(0.0, 0.0))
    shots = []
    height = 14 * spacing + 20.0
    w.add_body(Polygon.box(WALL_T, height), kind="static", position=(WALL_X, 0.5 * height - 10.0), name="wall")
    y = 0.0
    specs = [(Polygon.box(0.25, 0.25), 0.0, 0.0), (Polygon.box(0.25, 0.25), math.pi / 4, 0.0),
             (Polygon.box(0.25, 0.25), 0.3, 1.0), (Circle(0.1), 0.0, 0.0), (Circle(0.1), 0.0, 1.0),
             (Polygon.box(1.0, 0.005), 0.0, 0.0), (Polygon.regular(5, 0.15), 0.1, 0.5)]
    for i, (shape, ang, e) in enumerate(specs):
        for x0 in (0.0, 3.3):  # two phases of the 16.7 m stride against the wall
            b = w.add_body(shape, position=(x0, y), angle=ang, velocity=(speed, 0.0), restitution=e,
                           name=f"shot{len(shots)}")
            shots.append(b)
            y += spacing
    crossed = set()
    vmax = [0.0]

    def each(k):
        for b in shots:
            if b.center_of_mass[0] > WALL_X:
                crossed.add(b.name)
            vmax[0] = max(vmax[0], float(np.hypot(*b.velocity)))

    k, exc = run_steps(w, steps, each)
    if exc:
        return _err_outcome(exc, k)
    m = dict(tunnelled=len(crossed), shots=len(shots), max_speed=vmax[0], finite=all_finite(w),
             names=sorted(crossed))
    fig = f"{len(crossed)}/{len(shots)} tunnelled, max speed after {vmax[0]:.0f} m/s"
    if crossed or vmax[0] > speed * (1 + 1e-6) or not m["finite"]:
        return Outcome(FAILED, fig, m)
    return Outcome(HELD, fig, m)


def volley(solver: str, speed: float = 1000.0) -> Outcome:
    """The same 14 bodies at 1000 m/s, but 3 m apart (a shotgun volley): their swept boxes
    overlap, so the broad phase pairs them with each other as well as with the wall."""
    return bullets(solver, speed, spacing=3.0)


# ---------------------------------------------------------------------------
# scale
# ---------------------------------------------------------------------------
def scaled_stack(solver: str, size: float, count: int = 5, seconds: float = 4.0,
                 settings: dict | None = None) -> Outcome:
    """``count`` boxes of side ``size`` stacked on static ground (placed touching), 4 s.

    Figures relative to the box size: the top box's height error (sink) and the
    largest sideways drift.  Held below 10%, degraded below 50% (still a stack).
    """
    w = world(solver, settings=settings)
    ground(w, width=40 * size, thickness=size)
    boxes = [w.add_body(Polygon.box(size, size), position=(0, size * (i + 0.5)), name=f"b{i}")
             for i in range(count)]
    k, exc = run_steps(w, int(round(seconds / w.dt)))
    if exc:
        return _err_outcome(exc, k)
    top = boxes[-1]
    sink = abs(top.center_of_mass[1] - size * (count - 0.5)) / size
    drift = max(abs(b.center_of_mass[0]) for b in boxes) / size
    tilt = max(abs(math.remainder(b.angle, math.pi / 2)) for b in boxes)
    m = dict(sink=sink, drift=drift, tilt=tilt, finite=all_finite(w))
    fig = f"sink {100 * sink:.1f}%, drift {100 * drift:.1f}% of size"
    if not m["finite"]:
        return Outcome(FAILED, fig, m)
    worst = max(sink, drift)
    return Outcome(HELD if worst < 0.1 else DEGRADED if worst < 0.5 else FAILED, fig, m)


def small_stack(solver, **kw):
    """Five 0.01 m boxes stacked (see ``scaled_stack``)."""
    return scaled_stack(solver, 0.01, **kw)


def large_stack(solver, **kw):
    """Five 100 m boxes stacked (see ``scaled_stack``)."""
    return scaled_stack(solver, 100.0, **kw)


def pyramid(w: World, rows: int, origin=(0.0, 0.0), size=1.0):
    ox, oy = origin
    ground(w, width=4 * rows * size, x=ox, top=oy)
    out = []
    for r in range(rows):
        for c in range(rows - r):
            x = ox + (c - 0.5 * (rows - r - 1)) * size * 1.0
            y = oy + (r + 0.5) * size
            out.append(w.add_body(Polygon.box(size, size), position=(x, y)))
    return out


FAR = (6000.0, 8000.0)  # 10 km from the origin


def far_pyramid(solver: str, rows: int = 10, steps: int = 300) -> Outcome:
    """A 10-row box pyramid (55 boxes) at the origin and the same one 10 km away
    (6000, 8000), 5 s each.  Figures: the largest difference between the two
    (relative positions) and the largest drift of the far one from its layout.
    Held when they differ by < 1 cm and the far one drifts < 5 cm.
    """
    runs = []
    for origin in ((0.0, 0.0), FAR):
        w = world(solver)
        boxes = pyramid(w, rows, origin)
        start = np.array([b.center_of_mass for b in boxes])
        k, exc = run_steps(w, steps)
        if exc:
            return _err_outcome(exc, k)
        end = np.array([b.center_of_mass for b in boxes])
        runs.append((start - np.array(origin), end - np.array(origin)))
    diff = float(np.max(np.abs(runs[0][1] - runs[1][1])))
    drift_far = float(np.max(np.hypot(*(runs[1][1] - runs[1][0]).T)))
    drift_origin = float(np.max(np.hypot(*(runs[0][1] - runs[0][0]).T)))
    m = dict(difference=diff, drift_far=drift_far, drift_origin=drift_origin,
             finite=bool(np.all(np.isfinite(runs[1][1]))))
    fig = f"far vs origin {diff * 1000:.2g} mm; drift {drift_far * 1000:.3g} mm (origin {drift_origin * 1000:.3g} mm)"
    if not m["finite"]:
        return Outcome(FAILED, fig, m)
    if diff < 0.01 and drift_far < 0.05:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if diff < 0.5 and drift_far < 0.5 else FAILED, fig, m)


def ten_thousand(solver: str, steps: int = 120, count: int = 10_000) -> Outcome:
    """10 000 boxes (0.4 m) in a 200 x 50 grid dropped 5 cm onto static ground, 2 s.

    Figures: ms per step, bodies below the ground (tunnelled), energy rise over the
    initial total.  Held: finite, nothing through the ground, no energy gained.
    """
    w = world(solver)
    cols = 200
    rows = count // cols
    ground(w, width=cols * 0.5 + 20)
    boxes = []
    for r in range(rows):
        for c in range(cols):
            boxes.append(w.add_body(Polygon.box(0.4, 0.4), position=((c - cols / 2) * 0.5, 0.25 + r * 0.5)))
    e0 = total_energy(w)
    t0 = time.perf_counter()
    k, exc = run_steps(w, steps)
    ms = 1000 * (time.perf_counter() - t0) / max(k, 1)
    if exc:
        return _err_outcome(exc, k, ms_per_step=ms)
    n = w._bodies.n
    B = w._bodies.view
    dyn = B.kind[:n] == 0
    below = int(np.sum(B.x[:n, 1][dyn] < 0.0))
    rise = total_energy(w) - e0
    m = dict(ms_per_step=ms, below=below, energy_rise=rise, e0=e0, finite=all_finite(w))
    fig = f"{ms:.0f} ms/step, {below} through ground, energy {rise:+.3g} J"
    if not m["finite"] or below or rise > 1e-6 * abs(e0):
        return Outcome(FAILED, fig, m)
    return Outcome(HELD, fig, m)


# ---------------------------------------------------------------------------
# degenerate geometry
# ---------------------------------------------------------------------------
NEAR_COLLINEAR = Polygon([(-0.5, -0.5), (0.0, -0.5 - 1e-7), (0.5, -0.5), (0.5, 0.5), (0.0, 0.5 + 1e-7),
                          (-0.5, 0.5)])


def near_collinear(solver: str, steps: int = 480) -> Outcome:
    """Boxes with an extra vertex 1e-7 m off the middle of the top and bottom edges
    (a 2e-7 rad turn), dropped tilted onto ground and stacked three high, 8 s (plain boxes
    rest after 4 s; these still rock at 0.07 m/s then).

    Figures: sink into the ground / each other and the largest speed at the end.
    Held: rests (speed < 0.05 m/s) with sink < 2 cm.
    """
    w = world(solver)
    ground(w)
    bs = [w.add_body(NEAR_COLLINEAR, position=(0.1 * i, 0.55 + 1.05 * i), angle=0.02 * (i - 1), name=f"p{i}")
          for i in range(3)]
    k, exc = run_steps(w, steps)
    if exc:
        return _err_outcome(exc, k)
    sink = max(0.0, -lowest_y(bs[0]))
    for lo, hi in zip(bs, bs[1:]):
        sink = max(sink, highest_y(lo) - lowest_y(hi))
    speed = max(np.hypot(*b.velocity) for b in bs)
    upright = all(b.center_of_mass[1] > a.center_of_mass[1] + 0.5 for a, b in zip(bs, bs[1:]))
    m = dict(sink=sink, speed=speed, upright=upright, finite=all_finite(w))
    fig = f"sink {sink * 1000:.1f} mm, speed {speed:.2g} m/s"
    if not m["finite"]:
        return Outcome(FAILED, fig, m)
    if sink < 0.02 and speed < 0.05 and upright:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if sink < 0.5 else FAILED, fig, m)


def slivers(solver: str, steps: int = 300) -> Outcome:
    """Slivers 1 m x 1 mm (aspect 1:1000): one dropped flat, one at 30 degrees, one
    falling end-first at 10 m/s, then three more stacked flat; 5 s.

    Figures: the deepest point below the ground surface (tunnelling if < -1 mm
    thickness... held when nothing goes below -5 mm), energy rise, rest speed.
    """
    w = world(solver)
    ground(w)
    sl = Polygon.box(1.0, 0.001)
    bs = [w.add_body(sl, position=(-3, 0.3), name="flat"),
          w.add_body(sl, position=(0, 1.0), angle=math.pi / 6, name="tilted"),
          w.add_body(sl, position=(3, 1.0), angle=math.pi / 2, velocity=(0, -10), name="end-on")]
    for i in range(3):
        bs.append(w.add_body(sl, position=(6 + 0.01 * i, 0.0005 + 0.001 * i + 0.0001 * i), name=f"stack{i}"))
    e0 = total_energy(w)
    rise = [0.0]
    deepest = [0.0]

    def each(k):
        rise[0] = max(rise[0], total_energy(w) - e0)
        deepest[0] = min(deepest[0], min(lowest_y(b) for b in bs))

    k, exc = run_steps(w, steps, each)
    if exc:
        return _err_outcome(exc, k)
    speed = max(np.hypot(*b.velocity) for b in bs)
    m = dict(deepest=deepest[0], energy_rise=rise[0], speed=speed, finite=all_finite(w))
    fig = f"deepest {deepest[0] * 1000:.2g} mm, energy rise {rise[0]:.2g} J, speed {speed:.2g} m/s"
    if not m["finite"] or deepest[0] < -0.25 or rise[0] > 0.05:
        return Outcome(FAILED, fig, m)
    if deepest[0] > -0.005 and speed < 0.05 and rise[0] <= 1e-3:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED, fig, m)


def coincident(solver: str, count: int = 8, steps: int = 300) -> Outcome:
    """Eight 1 m boxes created exactly on top of each other (no gravity), 5 s.

    Figures: the largest body speed while separating (the push-out must be
    capped: held below 10 m/s, failed above 100 m/s = an explosion), the deepest
    remaining overlap, and linear momentum (starts at zero).
    """
    w = world(solver, gravity=(0.0, 0.0))
    bs = [w.add_body(Polygon.box(1, 1), position=(0.0, 0.0), name=f"c{i}") for i in range(count)]
    vmax = [0.0]

    def each(k):
        vmax[0] = max(vmax[0], max(float(np.hypot(*b.velocity)) for b in bs))

    k, exc = run_steps(w, steps, each)
    if exc:
        return _err_outcome(exc, k)
    depth = max([c.depth for c in w.contacts()] + [0.0])
    p = float(np.hypot(*w.linear_momentum()))
    m = dict(max_speed=vmax[0], depth=depth, momentum=p, finite=all_finite(w))
    fig = f"max speed {vmax[0]:.2g} m/s, overlap left {depth * 1000:.1f} mm"
    if not m["finite"] or vmax[0] > 100:
        return Outcome(FAILED, fig, m)
    if vmax[0] <= 10 and depth < 0.02:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if depth < 0.5 else FAILED, fig, m)


# ---------------------------------------------------------------------------
# long run
# ---------------------------------------------------------------------------
TUMBLER_R, TUMBLER_W = 3.0, 0.5  # drum radius, angular speed (rad/s)


def tumbler(solver: str, sides: int = 12, shapes: int = 24) -> World:
    """A reduced tumbler: a 12-sided drum (radius 3 m) of kinematic wall boxes whose
    position and velocity are driven on the circle every step, with 24 mixed
    bodies inside.  ``drive(w)`` advances the walls."""
    w = world(solver)
    walls = []
    for i in range(sides):
        walls.append(w.add_body(Polygon.box(2 * TUMBLER_R * math.tan(math.pi / sides) + 0.2, 0.3),
                                kind="kinematic", name=f"wall{i}"))
    w._tumbler = (walls, sides)
    rng = np.random.default_rng(7)
    for i in range(shapes):
        x = -1.5 + (i % 6) * 0.6
        y = -1.2 + (i // 6) * 0.6
        kind = i % 3
        shape = (Polygon.box(0.4, 0.3) if kind == 0 else Circle(0.2) if kind == 1
                 else Polygon.regular(5, 0.22))
        w.add_body(shape, position=(x, y), angle=float(rng.uniform(0, 1)), restitution=0.2, name=f"s{i}")
    _place_walls(w, 0.0)
    return w


def _place_walls(w: World, phase: float) -> None:
    walls, sides = w._tumbler
    r = TUMBLER_R + 0.15
    for i, b in enumerate(walls):
        a = phase + 2 * math.pi * i / sides
        c = (r * math.sin(a), -r * math.cos(a))
        b.angle = a
        b.position = c
        b.velocity = (TUMBLER_W * r * math.cos(a), TUMBLER_W * r * math.sin(a))
        b.angular_velocity = TUMBLER_W


def drive(w: World) -> None:
    """Put the drum walls where the drive says at the current time (no drift)."""
    _place_walls(w, TUMBLER_W * w.time)


def long_run(solver: str, steps: int = 100_000, check_every: int = 100) -> Outcome:
    """100 000 steps (27.8 min simulated) of the reduced tumbler.

    Figures: the largest total energy of the contents (kinetic + potential about the
    drum centre) in the last tenth of the run against the first tenth, and how
    many bodies left the drum.  Held: finite, none escaped, late energy at most
    1.5x early energy (no secular growth).
    """
    w = tumbler(solver)
    walls = set(w._tumbler[0])
    inside = [b for b in w.bodies if b not in walls]
    energies = []
    escaped = set()
    t0 = time.perf_counter()
    for k in range(steps):
        drive(w)
        try:
            w.step()
        except SimulationError as exc:
            return _err_outcome(exc, k)
        if k % check_every == 0:
            e = 0.0
            for b in inside:
                v = b.velocity
                e += 0.5 * b.mass * (v[0] ** 2 + v[1] ** 2) + 0.5 * b.inertia * b.angular_velocity ** 2 \
                    + b.mass * 9.81 * b.center_of_mass[1]
                if np.hypot(*b.center_of_mass) > TUMBLER_R + 0.5:
                    escaped.add(b.name)
            energies.append(e)
    secs = time.perf_counter() - t0
    e = np.array(energies)
    tenth = max(1, len(e) // 10)
    floor = -sum(b.mass for b in inside) * 9.81 * TUMBLER_R  # all at the drum bottom
    early = e[:tenth].max() - floor
    late = e[-tenth:].max() - floor
    peak = e.max() - floor
    m = dict(early=early, late=late, ratio=late / early, peak_ratio=peak / early, escaped=len(escaped),
             seconds=secs, steps=steps, finite=bool(np.all(np.isfinite(e))) and all_finite(w))
    fig = (f"late/early energy {late / early:.2f} (peak {peak / early:.2f}), {len(escaped)} escaped, "
           f"{secs:.0f} s for {steps} steps")
    if not m["finite"] or escaped:
        return Outcome(FAILED, fig, m)
    if late / early <= 1.5:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if late / early <= 3 else FAILED, fig, m)


# ---------------------------------------------------------------------------
# the table
# ---------------------------------------------------------------------------
@dataclass
class Probe:
    name: str
    regime: str
    fn: object
    advice: str
    quick_kw: dict = field(default_factory=dict)


PROBES = [
    Probe("mass ratio: stack", "1000 kg box on a 1 kg box", mass_ratio_stack,
          "Sub-stepping is what carries a heavy load on a light body: use soft_step (raise substeps for "
          "larger ratios). sequential_impulse fails here (projected Gauss-Seidel at 1000:1, as in Box2D "
          "2.x; the block solver and 64 velocity iterations do not help)."),
    Probe("mass ratio: spring chain", "1 kg links in a spring chain (k 2e4) carrying 100 kg", spring_chain,
          "Every mode settles it: soft_step and sequential_impulse solve their stiff springs together "
          "(backward Euler on the whole chain), the seed modes sub-step their explicit springs."),
    Probe("stiff spring", "k = 1e6 N/m on 1 kg at dt = 1/60 (k dt^2/m = 278)", stiff_spring,
          "soft_step or sequential_impulse (implicit springs: stable, energy is damped, not gained); an "
          "explicit mode must sub-step or it refuses the step."),
    Probe("speed", "1000 m/s bodies against a 1 cm wall", bullets,
          "Modes with speculative contacts (soft_step, sequential_impulse) stop bullets; avoid modes "
          "without continuous collision for fast bodies."),
    Probe("speed: volley", "14 bodies at 1000 m/s, 3 m apart, against a 1 cm wall", volley,
          "soft_step or sequential_impulse: pairs that cannot meet within the step get no speculative "
          "rows, so fast neighbours fly past each other."),
    Probe("scale: 1 cm", "five 0.01 m boxes stacked", small_stack,
          "soft_step with substeps=16, contact_hertz=120 (sink < 10%, see tests/extremes/test_scale.py); "
          "better, model in metres with bodies >= 0.1 m."),
    Probe("scale: 100 m", "five 100 m boxes stacked", large_stack,
          "Large bodies are fine; keep sizes within 0.1..100 m for the default tolerances."),
    Probe("far from origin", "55-box pyramid 10 km from the origin vs at it", far_pyramid,
          "Doubles hold at 10 km: soft_step and sequential_impulse match the origin run to 1e-8 mm."),
    Probe("10 000 bodies", "10 000 boxes dropped in a 200 x 50 grid", ten_thousand,
          "Use soft_step with sleeping on; cost grows linearly with the number of contacts.",
          quick_kw=dict(count=2000, steps=60)),
    Probe("near-collinear", "extra vertex 1e-7 m off a box edge, stacked three high", near_collinear,
          "Safe in every mode that held; Polygon.hull drops such vertices if you prefer."),
    Probe("slivers", "1 m x 1 mm boxes (1:1000), dropped, end-on at 10 m/s, stacked", slivers,
          "soft_step (sub-steps and rotation cap); give slivers some thickness (>= 1 cm) otherwise."),
    Probe("coincident bodies", "eight boxes created on top of each other", coincident,
          "soft_step separates them gently (push_out_speed, default 3 m/s); penalty/hybrid cap their "
          "push-out too (push_out_speed, default 2 m/s)."),
    Probe("long run", "reduced tumbler, 100 000 steps", long_run,
          "soft_step for long unattended runs.", quick_kw=dict(steps=5000)),
]


def run_probe(probe: Probe, solver: str, quick: bool = False, **kw) -> Outcome:
    if solver not in physics.solvers_available():
        return Outcome(UNAVAILABLE, "mode not available")
    t0 = time.perf_counter()
    try:
        out = probe.fn(solver, **(dict(probe.quick_kw) if quick else {}), **kw)
    except Exception as exc:  # a crash is an outcome too: report it, keep going
        out = Outcome(FAILED, f"crashed: {type(exc).__name__}: {exc}"[:160])
    out.seconds = time.perf_counter() - t0
    return out


def render(results: dict, modes: list[str], quick: bool, elapsed: float) -> str:
    lines = [
        "# Reliability at the extremes",
        "",
        "Generated by `python -m bench.reliability` from real runs"
        + (" (**--quick**: reduced sizes)" if quick else "") + f" on {platform.machine()} / "
        f"Python {platform.python_version()}, {time.strftime('%Y-%m-%d')}; {elapsed:.0f} s in total. "
        "Each probe runs one extreme scene in each solver mode with that mode's default settings "
        "(dt = 1/60). The probes are the functions in `bench/reliability.py`; `tests/extremes/` "
        "asserts the same figures.",
        "",
        "- **held**: the claim holds (finite, bounded energy, no tunnelling, drift below the bound "
        "stated in the probe);",
        "- **degraded**: finite and honest, but only approximately (sinks or drifts beyond the bound, "
        "less than a body size), or the step was refused with a clear `SimulationError` where that "
        "is an acceptable answer;",
        "- **failed**: tunnelling, energy growth, non-finite values reaching the user, an unexplained "
        "error, or a miss by more than a body size.",
        "",
        "| probe | regime | " + " | ".join(modes) + " | choose |",
        "|---|---|" + "---|" * len(modes) + "---|",
    ]
    for probe in PROBES:
        row = results[probe.name]
        cells = [f"**{row[m].status}**: {row[m].figure}".replace("|", "/") for m in modes]
        held = [m for m in modes if row[m].status == HELD]
        pick = f"{', '.join(held)}. " if held else "nothing held. "
        lines.append(f"| {probe.name} | {probe.regime} | " + " | ".join(cells) + f" | {pick}{probe.advice} |")
    lines += ["", "## Probes", ""]
    for probe in PROBES:
        doc = " ".join((probe.fn.__doc__ or "").split())
        lines.append(f"- **{probe.name}** (`{probe.fn.__name__}`): {doc}")
    lines += ["", "## Cost per probe (s)", "", "| probe | " + " | ".join(modes) + " |",
              "|---|" + "---|" * len(modes)]
    for probe in PROBES:
        lines.append(f"| {probe.name} | " + " | ".join(f"{results[probe.name][m].seconds:.1f}" for m in modes) + " |")
    lines.append("")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="reduced sizes (10 000 bodies -> 2000, long run -> 5000 steps)")
    ap.add_argument("--modes", default="", help="comma-separated solver modes (default: every available mode)")
    ap.add_argument("--probes", default="", help="comma-separated probe function names (default: all)")
    ap.add_argument("--out", default=str(DOC))
    a = ap.parse_args(argv)
    modes = [m for m in a.modes.split(",") if m] or physics.solvers_available()
    probes = [p for p in PROBES if not a.probes or p.fn.__name__ in a.probes.split(",")]
    results = {}
    t0 = time.perf_counter()
    for probe in probes:
        results[probe.name] = {}
        for mode in modes:
            out = run_probe(probe, mode, quick=a.quick)
            results[probe.name][mode] = out
            print(f"{probe.name:22s} {mode:20s} {out} ({out.seconds:.1f} s)", flush=True)
    if len(probes) == len(PROBES):
        Path(a.out).write_text(render(results, modes, a.quick, time.perf_counter() - t0))
        print(f"wrote {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
