"""``python -m bench.reliability``: every probe in every mode, printed and written to the docs."""
from __future__ import annotations

import argparse
import time
from pathlib import Path

import physics

from ..paths import RELIABILITY_DOC as DOC
from .probes import PROBES, run_probe
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
    ap.add_argument("--box2d-live", action="store_true", help="with --samples: run Box2D v3 now, not its recorded figures")
    a = ap.parse_args(argv)
    if a.samples:
        from .samples import main_samples
        return main_samples(a.out, a.only, a.box2d_live)
    modes = [m for m in a.modes.split(",") if m] or physics.solvers_available()
    wanted = [n for n in a.probes.split(",") if n]
    known = [p.measure.__name__ for p in PROBES]
    if set(wanted) - set(known):
        ap.error(f"unknown probe {', '.join(sorted(set(wanted) - set(known)))} (probes: {', '.join(known)})")
    probes = [p for p in PROBES if not wanted or p.measure.__name__ in wanted]
    results = {}
    t0 = time.perf_counter()
    for probe in probes:
        results[probe.name] = {}
        for mode in modes:
            out = run_probe(probe, mode, quick=a.quick)
            results[probe.name][mode] = out
            print(f"{probe.name:22s} {mode:20s} {out} ({out.seconds:.1f} s)", flush=True)
    if len(probes) == len(PROBES):
        from .samples import keep_section
        Path(a.out).write_text(keep_section(Path(a.out), render(results, modes, a.quick, time.perf_counter() - t0)))
        print(f"wrote {a.out}")
    return 0
