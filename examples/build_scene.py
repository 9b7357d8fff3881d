"""Build a scene file in code, validate it, and see what a broken one reports.

A scene is plain JSON (see the scene format page). This script writes one from Python data:
a staircase of static steps, a row of balls of rising restitution and a box hanging on a
spring, checks it three ways (against the published JSON Schema with jsonschema, as any
external tool can; by loading it with `physics.load_scene`; with `python -m physics
validate`), then breaks three fields on purpose and prints the problems the loader lists,
each with its JSON path.

Run: `python examples/build_scene.py [--out FILE]`
"""
from __future__ import annotations

import argparse
import copy
import json
import subprocess
import sys
from pathlib import Path

import jsonschema

import physics
from physics.scene import scene_from_dict

SCHEMA = Path(__file__).resolve().parents[1] / "scenes" / "stelkropp.schema.json"


def staircase_scene() -> dict:
    """The scene as Python data: exactly what the JSON file will hold."""
    bodies = [{"name": "floor", "kind": "static", "shape": {"box": [30, 1]}, "position": [0, -0.5]}]
    for i in range(6):  # static steps, 1 m deep and 0.4 m high each
        bodies.append({"name": f"step{i}", "kind": "static", "shape": {"box": [1, 0.4 * (i + 1)]},
                       "position": [-8 + i, 0.2 * (i + 1)]})
    for i, e in enumerate((0.0, 0.25, 0.5, 0.75, 0.95)):
        bodies.append({"name": f"ball{i}", "shape": {"circle": 0.3}, "position": [2 + 1.5 * i, 4],
                       "restitution": e, "friction": {"static": 0.4, "dynamic": 0.3}})
    bodies.append({"name": "crate", "shape": {"box": [0.8, 0.8]}, "position": [-7.5, 5], "density": 2})
    return {
        "$schema": "stelkropp.schema.json",
        "format": "stelkropp.scene", "version": 1,
        "name": "Staircase", "description": "Built by examples/build_scene.py",
        "world": {"gravity": [0, -9.81], "dt": 1 / 60, "solver": "soft_step", "settings": {"substeps": 4}},
        "camera": {"center": [0, 3], "zoom": 40},
        "bodies": bodies,
        "springs": [{"name": "hook", "a": "crate", "b": None, "anchor_a": [0, 0.4], "anchor_b": [-7.5, 7],
                     "stiffness": 120, "damping": 2}],
    }


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=Path("staircase.json"), help="where to write the scene")
    args = ap.parse_args(argv)
    data = staircase_scene()

    jsonschema.validate(data, json.loads(SCHEMA.read_text()))  # raises ValidationError if not
    print(f"schema: valid against {SCHEMA.name}")
    args.out.write_text(json.dumps(data, indent=1) + "\n")
    world = physics.load_scene(args.out)  # everything the schema cannot say is checked here too
    print(f"loaded: {len(world.bodies)} bodies, {len(world.springs)} springs, solver {world.solver}")
    cli = subprocess.run([sys.executable, "-m", "physics", "validate", str(args.out)],
                         capture_output=True, text=True)
    print(f"cli: {cli.stdout.strip()} (exit {cli.returncode})")

    broken = copy.deepcopy(data)
    broken["bodies"][7]["restitution"] = 1.5                                      # out of range
    broken["bodies"][1]["shape"] = {"polygon": [[0, 0], [2, 0], [1, 1], [2, 2], [0, 2]]}  # concave
    broken["springs"][0]["a"] = "crane"                                           # no such body
    try:
        scene_from_dict(broken, source="broken staircase")
    except physics.SceneError as exc:
        print(f"broken: {len(exc.problems)} problems")
        for path, reason in exc.problems:
            print(f"  {path}: {reason}")
    return cli.returncode


if __name__ == "__main__":
    raise SystemExit(main())
