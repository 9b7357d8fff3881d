"""Headless command line: ``python -m physics`` / ``stelkropp-sim``.

    simulate SCENE --steps N [--solver NAME] [--dt DT] [--set KEY=VALUE ...] [--out FILE] [--record K]
    validate SCENE...
    info SCENE [--json]
    schema                      print the scene format's JSON Schema
    tune SCENE --budget B [--steps N] [--metric M] [--apply] [--scheduler ADDR]   (physics/tuning/)

Exit codes: 0 success, 1 a bad scene or option, 2 the simulation produced
non-finite values (the state written is the last finite one, "finite": false).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time

from . import options
from .errors import SceneError, SimulationError

# world attributes --set may change besides the solver's own settings
WORLD_KEYS = ("gravity", "integrator", "sleeping", "broadphase", "narrowphase")


# the longest message printed for a bad option (the value itself may be megabytes)
MAX_MESSAGE_CHARS = 500


def main(argv=None) -> int:
    """Run the command line with ``argv`` (default sys.argv[1:]); returns the exit code."""
    _printable_output()
    args = _parser().parse_args(argv)
    try:
        return args.run(args)
    except SceneError as exc:
        print(exc, file=sys.stderr)
        return 1
    except BrokenPipeError:  # `... | head` closed the pipe: not an error of ours
        return 0


def _printable_output() -> None:
    """Escape what the terminal cannot encode (a file name that is not UTF-8 reaches us with lone
    surrogates) instead of dying with UnicodeEncodeError half-way through the output."""
    for stream in (sys.stdout, sys.stderr):
        if hasattr(stream, "reconfigure"):
            stream.reconfigure(errors="backslashreplace")


class _Parser(argparse.ArgumentParser):
    """argparse, but a bad option exits 1 as documented (exit code 2 means a non-finite run)."""

    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(1, f"{self.prog}: error: {_clip(message)}\n")


def _clip(text: str) -> str:
    return text if len(text) <= MAX_MESSAGE_CHARS else f"{text[:MAX_MESSAGE_CHARS - 40]}... ({len(text)} characters)"


def _parser() -> argparse.ArgumentParser:
    p = _Parser(prog="stelkropp-sim", description="Run, check and describe Stelkropp scene files.")
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
    from .tuning.command import add_parser as add_tune
    add_tune(sub, _count)
    pre = sub.add_parser("precompile", help="compile the kernels into numba's disk cache ahead of the first step")
    pre.add_argument("scenes", nargs="*", metavar="SCENE", help="compile what these scenes need (default: every mode)")
    pre.add_argument("--mode", action="append", choices=options.SOLVERS, help="every unit of this mode (repeatable)")
    pre.add_argument("--jobs", type=_count, default=0, help="worker processes (default: the machine's cores)")
    pre.set_defaults(run=precompile_cmd)
    sch = sub.add_parser("schema", help="print the scene format's JSON Schema (scenes/stelkropp.schema.json)")
    sch.set_defaults(run=schema)
    return p


def precompile_cmd(args) -> int:
    """``precompile``: the kernels of the given scenes (or modes, or all) into the cache, with a
    line of progress per unit (physics/compile_units.py)."""
    from .compile_units import default_jobs, precompile
    from .scene import load_scene
    jobs = args.jobs or default_jobs()
    t0 = time.time()
    if args.scenes:
        for path in args.scenes:
            precompile(load_scene(path), jobs=jobs)
    else:
        precompile(args.mode, jobs=jobs)
    print(f"precompiled in {time.time() - t0:.1f} s on {jobs} process(es)", file=sys.stderr)
    return 0


def _count(text: str) -> int:
    try:
        n = int(text) if len(text) <= 30 else -1
    except ValueError:
        n = -1
    if n < 0:
        raise argparse.ArgumentTypeError(f"expected a whole number >= 0 (at most 30 digits), got {_clip(repr(text))}")
    return n


# -- simulate -----------------------------------------------------------------
def simulate(args) -> int:
    from .scene import load_scene
    problem = args.out is not None and _out_problem(args.out)
    if problem:  # before the run, so a long simulation is never lost to a typo in --out
        print(f"--out {args.out}: {problem}", file=sys.stderr)
        return 1
    world = load_scene(args.scene)
    try:
        _configure(world, args)
    except (ValueError, KeyError, TypeError, OverflowError) as exc:
        print(f"{args.scene}: {_clip(str(exc.args[0] if exc.args else exc))}", file=sys.stderr)
        return 1
    result, code = _run(world, args.steps, args.record)
    text = json.dumps(_json_safe(result), allow_nan=False) + "\n"
    if args.out:
        from .scene.atomic import write_atomic
        try:
            write_atomic(args.out, text)
        except OSError as exc:
            print(f"--out {args.out}: cannot write it ({exc.strerror or exc}); the result follows on stdout",
                  file=sys.stderr)
            sys.stdout.write(text)
            return 1
    else:
        sys.stdout.write(text)
    if code:
        print(result["error"], file=sys.stderr)
    return code


def _out_problem(path: str) -> str | None:
    """Why ``--out path`` could not be written, checked before the run (None if it looks writable)."""
    from .scene.file_kind import kind_name
    target = os.path.realpath(path)
    if os.path.isdir(target):
        return "is a folder; give a file name"
    try:
        kind = kind_name(os.stat(target).st_mode)
    except OSError:
        kind = None
    if kind:
        return f"is {kind}, not a regular file; writing the result would replace it"
    folder = os.path.dirname(target)
    if not os.path.isdir(folder):
        return f"the folder {folder} does not exist"
    if not os.access(folder, os.W_OK | os.X_OK):
        return f"cannot write in the folder {folder}"
    try:
        limit = os.pathconf(folder, "PC_NAME_MAX")
    except (OSError, ValueError):
        limit = 255
    if len(os.fsencode(os.path.basename(target))) > limit:
        return f"the file name is longer than this file system allows ({limit} bytes)"
    return None


def _json_safe(value):
    """The result with non-finite numbers as null (its "finite" field already says so)."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _json_safe(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_json_safe(v) for v in value]
    return value


def _configure(world, args) -> None:
    if args.solver:
        world.solver = args.solver
    if args.dt is not None:
        world.dt = args.dt
    for item in args.set:
        key, value = parse_set_item(item, lambda k: _is_switch(world, k))
        if key in WORLD_KEYS:
            setattr(world, key, value)
        else:
            world.settings[key] = value


def parse_set_item(item: str, is_switch) -> tuple:
    """(key, value) of one ``--set KEY=VALUE``: the value as JSON or a bare word (``_value``), and
    for a key where ``is_switch(key)`` is true a bool from on/off, yes/no, true/false or 1/0
    (``_switch``); ValueError naming the item or the key otherwise.  The caller checks the key and
    the value's range (a mode's setting: ``Setting.coerce``)."""
    key, sep, raw = item.partition("=")
    if not sep or not key:
        raise ValueError(f"--set expects KEY=VALUE, got {item!r}")
    value = _value(raw)
    if is_switch(key):
        value = _switch(key, raw, value)
    return key, value


# spellings of a yes/no option on the command line (issue 20: "--set sleeping=off" turned sleeping on)
_ON, _OFF = ("true", "on", "yes", "1"), ("false", "off", "no", "0")


def _is_switch(world, key: str) -> bool:
    """Whether ``key`` is a yes/no option: the world's ``sleeping`` or a mode's boolean setting."""
    if key == "sleeping":
        return True
    decl = world.settings.declared().get(key) if key not in WORLD_KEYS else None
    return decl is not None and decl.type is bool


def _switch(key: str, raw: str, value) -> bool:
    """``--set KEY=on|off|true|false|yes|no|1|0`` (any case) as a bool; ValueError naming ``key`` else."""
    if isinstance(value, bool):
        return value
    word = raw.strip().lower()
    if word in _ON or word in _OFF:
        return word in _ON
    raise ValueError(f"--set {key}: expected one of {', '.join(_ON + _OFF)}, got {_clip(repr(raw))}")


def _value(raw: str):
    """JSON if it parses (numbers, true, lists), else the bare word; NaN, Infinity and numbers
    beyond float range refused (ValueError)."""
    from .scene.json_io import NonFinite, parse
    try:
        v = parse(raw)
    except ValueError:
        return raw
    stack = [v]
    while stack:  # without recursion: the value may nest deeply
        x = stack.pop()
        if isinstance(x, NonFinite):
            shown = repr(raw) if len(raw) <= 80 else repr(raw[:60]) + f"... ({len(raw)} characters)"
            raise ValueError(f"--set value {shown} is not finite (or beyond the range of a float)")
        if isinstance(x, list):
            stack += x
        elif isinstance(x, dict):
            stack += x.values()
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
    if error is None and not result["finite"]:  # the world's finite check should have refused the step
        error = "the final state holds non-finite values"
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
    if data.get("integrator_note"):
        print(f"              ({data['integrator_note']})")
    print(f"  gravity:    {list(world.gravity)}   dt: {world.dt:g} s")
    print("  settings:   " + ", ".join(f"{k}={v}" for k, v in data["settings"].items()))
    for k, c in data["chosen"].items():  # chosen from the scene's content, where the file set none
        print(f"  chosen:     {k}={c['value']} ({c['why']}; set it to override)")
    print("  stages:     " + " -> ".join(data["stages"]))
    return 0


def schema(args) -> int:
    """Print the published JSON Schema of the scene format."""
    from .scene.schema import schema_text
    sys.stdout.write(schema_text())
    return 0
