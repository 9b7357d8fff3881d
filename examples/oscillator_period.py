"""A mass on a spring, measured against its analytic period T = 2 pi sqrt(m / k).

A 1 kg box hangs from a fixed point on an undamped spring (k = 40 N/m) under gravity and is
released at the spring's rest length, so it oscillates about the point where the spring
carries its weight. The script runs the world headless for ten seconds, finds the period
from the times the box turns at the top, prints it beside the analytic one and plots the
height against the analytic curve (matplotlib, no display needed).

Run: `python examples/oscillator_period.py [--solver NAME] [--plot FILE]`
"""
from __future__ import annotations

import argparse
import math

import numpy as np

import physics

MASS, STIFFNESS, SECONDS = 1.0, 40.0, 10.0


def simulate(solver: str):
    """Times (s) and heights (m) of the hanging box, one sample per step."""
    world = physics.World(gravity=(0.0, -9.81), dt=1 / 60, solver=solver)
    # a 0.5 m box of density 4 kg/m^2 weighs 1 kg; the spring's rest length is the 2 m it spans now
    box = world.add_body(physics.Polygon.box(0.5, 0.5), position=(0.0, 3.0), density=MASS / 0.25)
    world.add_spring(box, None, anchor_a=(0.0, 0.0), anchor_b=(0.0, 5.0), stiffness=STIFFNESS)
    t, y, vy = [0.0], [box.position[1]], [box.velocity[1]]
    for _ in range(round(SECONDS / world.dt)):
        world.step()
        t.append(world.time)
        y.append(box.position[1])
        vy.append(box.velocity[1])
    return np.array(t), np.array(y), np.array(vy)


def measured_period(t, vy) -> float:
    """Mean time between the tops of the swing: vertical velocity crossing zero downwards,
    each crossing placed by linear interpolation between the two steps around it."""
    k = np.nonzero((vy[:-1] > 0) & (vy[1:] <= 0))[0]
    tops = t[k] + (t[k + 1] - t[k]) * vy[k] / (vy[k] - vy[k + 1])
    if len(tops) < 2:
        raise RuntimeError("fewer than two full swings: nothing to measure")
    return float(np.diff(tops).mean())


def plot(t, y, period, path) -> None:
    import matplotlib
    matplotlib.use("Agg")  # files only: no window
    import matplotlib.pyplot as plt
    g = 9.81
    sag = MASS * g / STIFFNESS  # the equilibrium is this far below the release point
    analytic = (y[0] - sag) + sag * np.cos(2 * math.pi * t / period)
    fig, ax = plt.subplots(figsize=(8, 3.5))
    ax.plot(t, y, label="Stelkropp", lw=2)
    ax.plot(t, analytic, "--", label="analytic: y0 - s + s cos(2 pi t / T)", lw=1)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("height of the box (m)")
    ax.set_title(f"mass on a spring: m = {MASS:g} kg, k = {STIFFNESS:g} N/m, T = {period:.4f} s")
    ax.set_ylim(y.min() - 0.05, y.max() + 0.25)  # room for the legend above the curve
    ax.legend(loc="upper right", ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--solver", default="soft_step", help="solver mode (default soft_step)")
    ap.add_argument("--plot", default="oscillator_period.png", help="where to write the plot")
    args = ap.parse_args(argv)
    t, y, vy = simulate(args.solver)
    analytic = 2 * math.pi * math.sqrt(MASS / STIFFNESS)
    period = measured_period(t, vy)
    print(f"solver:          {args.solver}")
    print(f"analytic period: {analytic:.5f} s")
    print(f"measured period: {period:.5f} s")
    print(f"relative error:  {abs(period - analytic) / analytic:.3%}")
    plot(t, y, analytic, args.plot)
    print(f"plot:            {args.plot}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
