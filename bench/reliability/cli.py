"""``python -m bench.reliability``: every probe in every mode, printed and written to the docs."""
from __future__ import annotations

import argparse
import dataclasses
import sys
import time
from pathlib import Path

import physics

from ..paths import RELIABILITY_DOC as DOC
from ..sweep import Sweep, open_records, plain
from .outcome import Outcome
from .probes import PROBES, ProbeCase, probe_task
from .render import render

DESCRIPTION = "Reliability at the extremes: every probe in every solver mode -> docs/reliability.md."


def main(argv=None) -> int:
    """Run the probes chosen (every one by default) in every mode chosen; write the docs page
    when every probe ran.  Returns 0; an unknown probe name is argparse's error."""
    ap = argparse.ArgumentParser(description=DESCRIPTION)
    ap.add_argument("--quick", action="store_true", help="reduced sizes (10 000 bodies -> 2000, long run -> 5000 steps)")
    ap.add_argument("--modes", default="", help="comma-separated solver modes (default: every available mode)")
    ap.add_argument("--probes", default="", help="comma-separated probe function names (default: all)")
    ap.add_argument("--out", default=str(DOC))
    ap.add_argument("--samples", action="store_true", help="only Box2D v3's samples beside Box2D (samples.py)")
    ap.add_argument("--only", help="with --samples: figure functions whose name contains this (nothing written)")
    ap.add_argument("--set", action="append", metavar="NAME=VALUE", dest="settings",
                    help="with --samples: a soft_step setting instead of its default (repeatable; nothing "
                         "written; substeps=N leaves the figures that name their own, such as the cart's, as they are)")
    ap.add_argument("--box2d-live", action="store_true", help="with --samples: run Box2D v3 now, not its recorded figures")
    ap.add_argument("--scheduler", help="a Dask scheduler address (default: a local cluster, one one-thread "
                                        "worker per core), or 'inline' (this process)")
    ap.add_argument("--results", metavar="FILE", help="stream each finished probe to this JSON-lines file")
    ap.add_argument("--resume", action="store_true", help="with --results: skip the probes already in FILE")
    a = ap.parse_args(argv)
    if a.samples:
        from .samples import main_samples, parse_settings
        try:
            settings = parse_settings(a.settings)
        except ValueError as exc:
            ap.error(str(exc))
        return main_samples(a.out, a.only, a.box2d_live, settings)
    modes = [m for m in a.modes.split(",") if m] or physics.solvers_available()
    wanted = [n for n in a.probes.split(",") if n]
    known = [p.measure.__name__ for p in PROBES]
    if set(wanted) - set(known):
        ap.error(f"unknown probe {', '.join(sorted(set(wanted) - set(known)))} (probes: {', '.join(known)})")
    probes = [p for p in PROBES if not wanted or p.measure.__name__ in wanted]
    t0 = time.perf_counter()
    try:
        results = run_probes(probes, modes, a.quick, a.scheduler, a.results, a.resume)
    except (ValueError, ImportError, OSError) as exc:
        print(f"bench.reliability: {exc}", file=sys.stderr)
        return 1
    if len(probes) == len(PROBES):
        from .samples import keep_section
        Path(a.out).write_text(keep_section(Path(a.out), render(results, modes, a.quick, time.perf_counter() - t0)))
        print(f"wrote {a.out}")
    return 0


def run_probes(probes, modes, quick=False, scheduler=None, results=None, resume=False) -> dict:
    """{probe name: {mode: Outcome}} with every probe x mode run as a Dask task (bench/sweep.py;
    ``scheduler`` as there), each printed as it finishes; ``results``: a JSON-lines file that
    receives each one, ``resume``: skip those already in it."""
    cases = [ProbeCase(p.measure.__name__, m, quick) for p in probes for m in modes]
    names = {p.measure.__name__: p.name for p in probes}
    records = open_records(results, "reliability", {"quick": quick}, resume,
                           encode=lambda o: plain(dataclasses.asdict(o)), decode=lambda d: Outcome(**d))

    def show(case, out):
        print(f"{names[case.probe]:22s} {case.mode:20s} {out} ({out.seconds:.1f} s)", flush=True)
    try:
        with Sweep(scheduler, progress=False) as sweep:
            outs = sweep.map(probe_task, cases, journal=records, on_result=show)
    finally:
        if records is not None:
            records.close()
    table = {p.name: {} for p in probes}
    for case, out in zip(cases, outs):
        table[names[case.probe]][case.mode] = out
    return table
