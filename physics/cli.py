"""Headless command line: ``python -m physics`` / ``stelkropp-sim``.

    simulate SCENE --steps N [--solver NAME] [--dt DT] [--set KEY=VALUE ...] [--out FILE] [--record K]
    validate SCENE...
    info SCENE [--json]
    schema                      print the scene format's JSON Schema

Exit codes: 0 success, 1 a bad scene or option, 2 the simulation produced
non-finite values (the state written is the last finite one, "finite": false).
"""
from __future__ import annotations

import argparse
import json
import math
import sys

from .errors import SceneError, SimulationError

# world attributes --set may change besides the solver's own settings
WORLD_KEYS = ("gravity", "integrator", "sleeping", "broadphase", "narrowphase")


def main(argv=None) -> int:
    args = _parser().parse_args(argv)
    try:
        return args.run(args)
    except SceneError as exc:
        print(exc, file=sys.stderr)
        return 1
    except BrokenPipeError:  # `... | head` closed the pipe: not an error of ours
        return 0


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="stelkropp-sim", description="Run, check and describe Stelkropp scene files.")
    sub = p.add_subparsers(required=True, metavar="COMMAND")
    sim = sub.add_parser("simulate", help="run a scene headless and write the final state as JSON")
    sim.add_argument("scene")
    sim.add_argument("--steps", type=_count, required=True, help="number of steps")
    sim.add_argument("--solver", help="solver mode (default: the scene's)")
    sim.add_argument("--dt", type=float, help="time step in seconds (default: the scene's)")
    sim.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                     help="a solver setting (e.g. substeps=8) or one of " + ", ".join(WORLD_KEYS)
                     + "; VALUE is JSON (8, 0.5, true, [0,-10]) or a bare word")
    sim.add_argument("--out", help="write the JSON here instead of to stdout")
    sim.add_argument("--record", type=_count, metavar="K", help="also record the state every K steps")
    sim.set_defaults(run=simulate)
    val = sub.add_parser("validate", help="check scene files; print every problem")
    val.add_argument("scenes", nargs="+", metavar="SCENE")
    val.set_defaults(run=validate)
    inf = sub.add_parser("info", help="counts, solver, settings and the pipeline stages of a scene")
    inf.add_argument("scene")
    inf.add_argument("--json", action="store_true", help="print machine-readable JSON")
    inf.set_defaults(run=info)
    sch = sub.add_parser("schema", help="print the scene format's JSON Schema (scenes/stelkropp.schema.json)")
    sch.set_defaults(run=schema)
    return p


def _count(text: str) -> int:
    n = int(text)
    if n < 0:
        raise argparse.ArgumentTypeError(f"must be >= 0, got {n}")
    return n


# -- simulate -----------------------------------------------------------------
def simulate(args) -> int:
    from .scene import load_scene
    world = load_scene(args.scene)
    try:
        _configure(world, args)
    except (ValueError, KeyError) as exc:
        print(f"{args.scene}: {exc.args[0] if exc.args else exc}", file=sys.stderr)
        return 1
    result, code = _run(world, args.steps, args.record)
    text = json.dumps(result, allow_nan=False) + "\n"
    if args.out:
        from .scene.json_io import write_atomic
        write_atomic(args.out, text)
    else:
        sys.stdout.write(text)
    if code:
        print(result["error"], file=sys.stderr)
    return code


def _configure(world, args) -> None:
    if args.solver:
        world.solver = args.solver
    if args.dt is not None:
        world.dt = args.dt
    for item in args.set:
        key, sep, raw = item.partition("=")
        if not sep or not key:
            raise ValueError(f"--set expects KEY=VALUE, got {item!r}")
        value = _value(raw)
        if key in WORLD_KEYS:
            setattr(world, key, value)
        else:
            world.settings[key] = value


def _value(raw: str):
    """JSON if it parses (numbers, true, lists), else the bare word; NaN/Infinity refused."""
    from .scene.json_io import NonFinite, parse
    try:
        v = parse(raw)
    except ValueError:
        return raw
    if isinstance(v, NonFinite) or (isinstance(v, list) and any(isinstance(x, NonFinite) for x in v)):
        raise ValueError(f"--set value {raw!r} is not finite")
    return v


def _run(world, steps: int, record: int | None):
    from tqdm import tqdm
    frames = []
    error = None
    bar = tqdm(total=steps, unit="step", file=sys.stderr, disable=not sys.stderr.isatty())
    try:
        for k in range(steps):
            if record and k % record == 0:
                frames.append(state(world))
            try:
                world.step()
            except SimulationError as exc:
                error = str(exc)
                break
            bar.update(1)
    finally:
        bar.close()
    if record and error is None and steps % record == 0:
        frames.append(state(world))
    result = state(world)
    result["finite"] = error is None and _finite(result)
    if error is not None:
        result["error"] = error
    if record:
        result["frames"] = frames
    return result, (0 if error is None else 2)


def state(world) -> dict:
    """Time, step count and every body's motion state (unnamed bodies have "name": null)."""
    return {
        "time": world.time,
        "steps": world.steps,
        "bodies": [{"name": b.name, "position": list(b.position), "angle": b.angle,
                    "velocity": list(b.velocity), "angular_velocity": b.angular_velocity}
                   for b in world.bodies],
    }


def _finite(st) -> bool:
    return all(math.isfinite(x) for b in st["bodies"]
               for x in (*b["position"], b["angle"], *b["velocity"], b["angular_velocity"]))


# -- validate / info ------------------------------------------------------------
def validate(args) -> int:
    from .scene import load_scene
    failed = 0
    for path in args.scenes:
        try:
            world = load_scene(path)
        except SceneError as exc:
            failed += 1
            print(exc)
            continue
        print(f"{path}: ok ({len(world.bodies)} bodies, {len(world.springs)} springs)")
    return 1 if failed else 0


def info(args) -> int:
    from .scene import load_scene, scene_metadata
    world = load_scene(args.scene)
    data = {**scene_metadata(world), **world.info()}
    data.pop("camera", None)
    if args.json:
        print(json.dumps(data, indent=2))
        return 0
    print(f"{args.scene}: {data.get('name', '(unnamed)')}")
    if data.get("description"):
        print(f"  {data['description']}")
    kinds = ", ".join(f"{data.get(k, 0)} {k}" for k in ("dynamic", "static", "kinematic"))
    print(f"  bodies:     {data['bodies']} ({kinds})")
    print(f"  springs:    {data['springs']}")
    print(f"  solver:     {data['solver']}   integrator: {data['integrator']}   sleeping: {data['sleeping']}")
    print(f"  gravity:    {list(world.gravity)}   dt: {world.dt:g} s")
    print("  settings:   " + ", ".join(f"{k}={v}" for k, v in data["settings"].items()))
    print("  stages:     " + " -> ".join(data["stages"]))
    return 0


def schema(args) -> int:
    """Print the published JSON Schema of the scene format."""
    from .scene.schema import schema_text
    sys.stdout.write(schema_text())
    return 0
