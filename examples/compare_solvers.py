"""Compare two solver modes on the same scene: accuracy and speed, measured fairly.

Builds a pyramid of 55 unit boxes (10 rows) twice, one world per mode, and runs both for
five simulated seconds. The runs are interleaved in chunks of 30 steps (A, B, A, B, ...) so
that whatever else the machine does slows both alike, and the first chunk, which includes
compiling the kernels, is not timed. For each mode it prints the median milliseconds per
step, the ratio to the first mode, and how far the top box drifted from where it started
(a pyramid that holds drifts millimetres; one that collapses drifts metres).

Run: `python examples/compare_solvers.py [--modes soft_step,sequential_impulse] [--steps N]`
"""
from __future__ import annotations

import argparse
import math
import statistics
import time

import physics

ROWS, CHUNK = 10, 30


def pyramid(solver: str) -> tuple[physics.World, physics.Body]:
    """A ROWS-high pyramid of 1 m boxes on static ground; returns the world and the top box."""
    world = physics.World(gravity=(0.0, -10.0), dt=1 / 60, solver=solver, sleeping=False)
    world.add_body(physics.Polygon.box(40, 1), kind="static", position=(0, -0.5))
    top = None
    for row in range(ROWS):
        for i in range(ROWS - row):
            x = (i - (ROWS - row - 1) / 2) * 1.0
            top = world.add_body(physics.Polygon.box(1, 1), position=(x, 0.5 + row), friction=0.6)
    return world, top


def run_chunk(world: physics.World, steps: int) -> float:
    """Seconds for ``steps`` steps."""
    t0 = time.perf_counter()
    for _ in range(steps):
        world.step()
    return time.perf_counter() - t0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--modes", default="soft_step,sequential_impulse", help="comma-separated solver modes")
    ap.add_argument("--steps", type=int, default=300, help="steps per mode (default 300: 5 s)")
    args = ap.parse_args(argv)
    modes = args.modes.split(",")
    runs = {m: pyramid(m) for m in modes}
    start = {m: top.position for m, (_, top) in runs.items()}
    times = {m: [] for m in modes}
    for k in range(0, args.steps, CHUNK):
        for m in modes:  # interleaved: A, B, A, B, ...
            secs = run_chunk(runs[m][0], min(CHUNK, args.steps - k))
            if k:  # the first chunk compiles or loads the kernels
                times[m].append(secs / min(CHUNK, args.steps - k))
    print(f"pyramid of {ROWS * (ROWS + 1) // 2} boxes, {args.steps} steps of 1/60 s, chunks of {CHUNK} interleaved")
    print(f"{'mode':<20} {'ms/step':>8} {'ratio':>6} {'top-box drift (m)':>18}")
    base = statistics.median(times[modes[0]])
    for m in modes:
        ms = statistics.median(times[m])
        (x0, y0), (x1, y1) = start[m], runs[m][1].position
        print(f"{m:<20} {ms * 1e3:8.3f} {ms / base:6.2f} {math.hypot(x1 - x0, y1 - y0):18.5f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
