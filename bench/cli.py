"""The benchmark suite: scenes x solver modes x settings, beside pymunk, pybox2d and Box2D v3.

    python -m bench                 # full run (< 20 min on 2 cores): results, plots, table
    python -m bench --quick         # CI smoke (< 2 min): defaults only, short runs
    python -m bench --write-docs    # full run, then rewrite docs/benchmarks.md
    python -m bench --docs-only     # re-plot and rewrite the docs from bench/results/bench.json
    python -m bench --scheduler tcp://HOST:8786   # the speed and accuracy cases on a Dask cluster

The speed and accuracy cases run as Dask tasks (bench/sweep.py): by default a local cluster of
one one-thread worker per core, so a timing case has its worker to itself; every finished case
streams to OUT/cases.jsonl and --resume skips those already there.

Speed: every configuration runs its scene in chunks of steps, interleaved chunk by
chunk with pymunk, pybox2d and Box2D v3 (built from its C sources, bench/box2d/) on
the identical scene (ours, pymunk, pybox2d, box2d_v3, ours, ...), after warm-up chunks
that are not timed; ms/step is the median over the timed chunks and the ratio to a
reference is the median of the per-chunk ratios, so machine noise that hits every
engine cancels.  An engine that cannot run here (no compiler for Box2D v3) is skipped
with the reason.  The first step (numba compile
or cache load) is timed apart and never enters ms/step.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

from .configs import QUICK_MODES, available_modes
from .engines import ENGINES, REF_ENGINES
from .paths import RESULTS
from .report.docs import write_docs
from .report.files import write_outputs
from .report.terminal import print_report
from .scenes import SCENES
from .session import PARTS, RunOptions, run


def parser() -> argparse.ArgumentParser:
    """The command line of ``python -m bench``."""
    ap = argparse.ArgumentParser(prog="python -m bench", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="CI smoke: default settings only, short runs (< 2 min)")
    ap.add_argument("--out", type=Path, default=None,
                    help="results directory (default bench/results, or bench/results/quick with --quick)")
    ap.add_argument("--modes", default=None, help="comma-separated solver modes (default: every available mode)")
    ap.add_argument("--scenes", default=None, help=f"comma-separated scenes from {list(SCENES)}")
    ap.add_argument("--parts", default="overhead,compile,speed,scaling,accuracy,profile",
                    help="comma-separated parts to run (default: all)")
    ap.add_argument("--no-refs", action="store_true", help="skip the reference engines (pymunk, pybox2d, Box2D v3)")
    ap.add_argument("--refs", default=None,
                    help=f"comma-separated reference engines (default: {','.join(REF_ENGINES)}; those that cannot run "
                         "here are skipped with the reason)")
    ap.add_argument("--box2d-src", default=None, metavar="DIR",
                    help="Box2D v3 source tree to build and measure (default: ../shared/reference/box2d-v3; "
                         "also $STELKROPP_BOX2D_SRC)")
    ap.add_argument("--no-compile", action="store_true", help="skip the cold/cached compile subprocesses")
    ap.add_argument("--budget", type=float, default=None, help="seconds per configuration and scene before it is cut")
    ap.add_argument("--write-docs", action="store_true", help="rewrite docs/benchmarks.md from this run")
    ap.add_argument("--docs-only", action="store_true", help="re-plot and rewrite the docs from the saved results")
    ap.add_argument("--scheduler", default=None,
                    help="a Dask scheduler address for the speed and accuracy cases (default: a local cluster, one "
                         "one-thread worker per core, so a timing case has its worker to itself; with --quick: "
                         "'inline', this process, since starting workers that load the kernels costs more than "
                         "the smoke run's few cases), or 'inline'")
    ap.add_argument("--resume", action="store_true",
                    help="skip the speed and accuracy cases already in OUT/cases.jsonl (where every finished case "
                         "streams as it arrives)")
    ap.add_argument("--tiny", action="store_true", help=argparse.SUPPRESS)  # tests: even smaller than --quick
    return ap


def options(a, outdir=None) -> RunOptions:
    """RunOptions from parsed arguments; SystemExit (argparse's error) for an unknown scene or part."""
    quick = a.quick or a.tiny
    modes = a.modes.split(",") if a.modes else available_modes()
    if quick and not a.modes:  # the smoke run: the default mode and the classic solver
        modes = [m for m in modes if m in QUICK_MODES] or modes[:1]
    parts = set(a.parts.split(","))
    if quick or a.no_compile:
        parts.discard("compile")
    scenes = a.scenes.split(",") if a.scenes else [k for k, s in SCENES.items() if not quick or s.quick]
    if a.tiny and not a.scenes:
        scenes = ["pyramid20"]
    bad = [s for s in scenes if s not in SCENES] + [p for p in parts if p not in PARTS]
    if bad:
        parser().error(f"unknown scene or part: {', '.join(bad)} (scenes: {', '.join(SCENES)}; "
                       f"parts: {', '.join(PARTS)})")
    if a.box2d_src:  # bench/box2d/build.py reads it wherever Box2D v3 is built or loaded
        os.environ["STELKROPP_BOX2D_SRC"] = str(a.box2d_src)
    refs = tuple(a.refs.split(",")) if a.refs else RunOptions.engines
    bad = [e for e in refs if e not in ENGINES]
    if bad:
        parser().error(f"unknown engine: {', '.join(bad)} (known: {', '.join(ENGINES)})")
    return RunOptions(modes=modes, scenes=scenes, parts=parts, engines=() if a.no_refs else refs,
                      quick=a.quick, tiny=a.tiny, budget_s=a.budget or 20.0,
                      scheduler=a.scheduler if a.scheduler is not None else ("inline" if quick else None),
                      results=None if outdir is None else Path(outdir) / "cases.jsonl", resume=a.resume)


def main(argv=None) -> int:
    """``python -m bench``: run, write results (and the docs), print the report; returns 0."""
    a = parser().parse_args(argv)
    outdir = a.out or (RESULTS / "quick" if (a.quick or a.tiny) else RESULTS)
    if a.docs_only:
        res = json.loads((outdir / "bench.json").read_text())
        write_outputs(res, outdir)
        print(f"wrote {write_docs(res, outdir)}")
        return 0
    outdir.mkdir(parents=True, exist_ok=True)
    try:
        res = run(options(a, outdir))
    except (ValueError, ImportError) as exc:  # an unreachable scheduler, a results file of another run
        print(f"bench: {exc}", file=sys.stderr)
        return 1
    pngs = write_outputs(res, outdir)
    print_report(res)
    print(f"\nresults: {outdir} ({', '.join(p.name for p in pngs)}); wall {res['meta']['wall_s']:.0f} s")
    if a.write_docs:
        print(f"wrote {write_docs(res, outdir)}")
    return 0
