"""Record a trajectory and export it to CSV and to numpy.

A ball dropped from 2 m onto the ground bounces (restitution 0.5) while a box is thrown
across it. `world.state()` is copied once per step, a numpy structured array with one row per
body, and the copies are stacked into one array of shape (steps + 1, bodies). That array is
written twice: as `trajectory.npz` (`numpy.load` gives it back with its field names) and as
`trajectory.csv`, one row per body and step, for a spreadsheet or pandas.

Run: `python examples/export_trajectory.py [--steps N] [--out DIR]`
"""
from __future__ import annotations

import argparse
import csv
from pathlib import Path

import numpy as np

import physics

COLUMNS = ["step", "time", "id", "name", "x", "y", "angle", "vx", "vy", "angular_velocity", "awake"]


def build() -> physics.World:
    world = physics.World(gravity=(0.0, -9.81), dt=1 / 60)
    world.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5), name="ground")
    world.add_body(physics.Circle(0.25), position=(0, 2.25), restitution=0.5, name="ball")
    world.add_body(physics.Polygon.box(0.5, 0.5), position=(-4, 1), velocity=(4, 3), angular_velocity=-2,
                   name="box")
    return world


def record(world: physics.World, steps: int):
    """(times, states): states[k] is world.state() after k steps."""
    times, states = [world.time], [world.state()]
    for _ in range(steps):
        world.step()
        times.append(world.time)
        states.append(world.state())
    return np.array(times), np.stack(states)


def write_csv(path: Path, times, states, names) -> int:
    """One row per body and step; returns the number of data rows."""
    rows = 0
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for k, (t, frame) in enumerate(zip(times, states)):
            for row in frame:
                x, y = row["position"]
                vx, vy = row["velocity"]
                w.writerow([k, repr(float(t)), int(row["id"]), names[int(row["id"])], repr(float(x)), repr(float(y)),
                            repr(float(row["angle"])), repr(float(vx)), repr(float(vy)),
                            repr(float(row["angular_velocity"])), int(row["awake"])])
                rows += 1
    return rows


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=180, help="steps to record (default 180: 3 s)")
    ap.add_argument("--out", type=Path, default=Path("."), help="folder for trajectory.csv and .npz")
    args = ap.parse_args(argv)
    world = build()
    names = {b.id: b.name for b in world.bodies}
    times, states = record(world, args.steps)
    args.out.mkdir(parents=True, exist_ok=True)
    npz = args.out / "trajectory.npz"
    np.savez(npz, time=times, state=states)  # a structured array keeps its field names
    rows = write_csv(args.out / "trajectory.csv", times, states, names)
    ball = states[:, 1]
    print(f"recorded {states.shape[0]} frames x {states.shape[1]} bodies, fields {states.dtype.names}")
    print(f"ball: lowest {ball['position'][:, 1].min():.3f} m, "
          f"highest after the first bounce {ball['position'][60:, 1].max():.3f} m")
    print(f"wrote {npz} (numpy.load(...)['state'])")
    print(f"wrote {args.out / 'trajectory.csv'} ({rows} rows)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
