"""The recorded end state of every shipped scene after 600 steps in every solver mode.

A refactor that claims "no change in behaviour" must reproduce these bit for bit
(tests/test_shipped_scenes.py compares against the record).  Where a change
deliberately alters a trajectory (a bug fix), re-record in the same commit and say
why in its message:

    .venv/bin/python -m tests.end_states                    # rewrites tests/data/end_states_600.json
    .venv/bin/python -m tests.end_states --solver hybrid    # only the entries of one mode (or --scene)

The digest is SHA-256 over the bodies' (x, q, v, w) in body order, as float64 bytes,
so a single flipped bit anywhere shows.
"""
from __future__ import annotations

import hashlib
import json
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
RECORD = ROOT / "tests" / "data" / "end_states_600.json"
SCENE_DIR = ROOT / "scenes"
STEPS = 600


def digest(world) -> str:
    """SHA-256 of every body's position, angle, velocity and angular velocity (float64 bytes)."""
    h = hashlib.sha256()
    for b in world.bodies:
        h.update(np.array([*b.center_of_mass, b.angle, *b.velocity, b.angular_velocity],
                          dtype=np.float64).tobytes())
    return h.hexdigest()


def run(name: str, solver: str, steps: int = STEPS):
    import physics
    w = physics.load_scene(SCENE_DIR / f"{name}.json")
    w.solver = solver
    for _ in range(steps):
        w.step()
    return w


def load_record() -> dict:
    return json.loads(RECORD.read_text())


def main(argv=None) -> int:
    import argparse

    import physics
    ap = argparse.ArgumentParser(description="record the 600-step end states")
    ap.add_argument("--solver", action="append", help="only this mode (repeatable)")
    ap.add_argument("--scene", action="append", help="only this scene (repeatable)")
    args = ap.parse_args(argv)
    names = sorted(p.stem for p in SCENE_DIR.glob("*.json") if p.name != "stelkropp.schema.json")
    out = load_record() if (args.solver or args.scene) and RECORD.exists() else {}
    for name in args.scene or names:
        for solver in args.solver or physics.solvers_available():
            out[f"{name}/{solver}"] = digest(run(name, solver))
            print(f"{name:18s} {solver:18s} {out[f'{name}/{solver}'][:16]}", flush=True)
    RECORD.parent.mkdir(parents=True, exist_ok=True)
    RECORD.write_text(json.dumps(out, indent=1, sort_keys=True) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
