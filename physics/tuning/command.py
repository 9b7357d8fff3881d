"""``python -m physics tune SCENE --steps N --budget B [--metric M] [--apply] [--scheduler ADDR]``."""
from __future__ import annotations

import json
import sys

from .metrics import METRICS


def add_parser(sub, count) -> None:
    """Register the ``tune`` command on the CLI's sub-parsers (``count`` parses a step count)."""
    p = sub.add_parser("tune", help="find the fastest solver settings within an error budget on a scene")
    p.add_argument("scene")
    p.add_argument("--steps", type=count, default=600, help="scene steps to compare over (default 600)")
    p.add_argument("--budget", required=True, help="error allowed (metres; energy_drift: a fraction)")
    p.add_argument("--metric", default="trajectory", help="one of " + ", ".join(METRICS))
    p.add_argument("--modes", help="comma-separated solver modes to search (default: all)")
    p.add_argument("--scheduler", help="a Dask scheduler address (default: a local cluster), or 'inline'")
    p.add_argument("--apply", action="store_true", help="write the chosen settings into the scene file")
    p.add_argument("--plot", metavar="PNG", help="save the speed/error plot here")
    p.add_argument("--all", action="store_true", help="list every candidate, not only the Pareto front")
    p.add_argument("--json", metavar="FILE", help="also write every candidate's numbers here as JSON")
    p.add_argument("--results", metavar="FILE", help="stream each finished run to this JSON-lines file")
    p.add_argument("--resume", action="store_true", help="with --results: skip the runs already in FILE")
    p.set_defaults(run=run)


def run(args) -> int:
    """The tune command: table and summary on stdout, exit 1 for bad options or no choice to apply."""
    from . import report
    from .apply import apply_choice
    from .search import tune
    try:
        budget = float(args.budget)
    except ValueError:
        budget = args.budget
    modes = args.modes.split(",") if args.modes else None
    try:
        result = tune(args.scene, steps=args.steps, metric=args.metric, budget=budget,
                      scheduler=args.scheduler, modes=modes, results=args.results, resume=args.resume)
    except (ValueError, ImportError) as exc:
        print(f"tune: {exc}", file=sys.stderr)
        return 1
    except OSError as exc:
        print(f"tune: results: cannot write {args.results} ({exc.strerror or exc})", file=sys.stderr)
        return 1
    print(report.table(result, all_rows=args.all))
    print(report.summary(result))
    if args.plot:
        report.plot(result, args.plot)
    if args.json:
        from ..scene.atomic import write_atomic
        write_atomic(args.json, json.dumps(_rows_json(result), indent=1) + "\n")
    if args.apply:
        if result.choice is None:
            print("tune: nothing applied: no candidate is within the budget", file=sys.stderr)
            return 1
        world = apply_choice(args.scene, result.choice["candidate"])
        print(f"applied to {args.scene}: {json.dumps(world)}")
    return 0


def _rows_json(result) -> dict:
    def clean(x):
        return x if not isinstance(x, float) or x == x and abs(x) != float("inf") else None
    rows = [{"key": r["key"], "seconds": r["seconds"], "error": clean(r["error"]), "within": r["within"],
             "front": r["front"], "refused": r["refused"],
             "measures": {k: clean(v) for k, v in r["measures"].items()}} for r in result.rows]
    return {"metric": result.metric, "budget": result.budget, "steps": result.steps,
            "converged": result.converged, "reference_gap": clean(result.reference_gap), "note": result.note,
            "choice": result.choice["key"] if result.choice else None, "rows": rows}
