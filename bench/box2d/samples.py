"""Measure Box2D v3 on its Stacking / Robustness samples and the issue-14/18 cases; write the figures.

    python -m bench.box2d.samples [--only PREFIX] [--out bench/results/box2d_v3_figures]

Conditions (issue 18): dt 1/60, 4 sub-steps (the Cart figures also at the sample's 12), sleeping
off, one thread, continuous collision on, every other setting Box2D's default or the sample's
own (contact tuning of Circle Stack, Overlap Recovery and Cart; joint tuning of Cart and Multiple
Prismatic). Each figure's JSON record says which body, time window and quantity it is; these
become the bounds of Stelkropp's accuracy tests.
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from dataclasses import asdict
from datetime import datetime, timezone
from pathlib import Path

from tqdm import tqdm

from ..suite import measures as M
from ..suite.samples import SAMPLES
from . import build as B
from .engine import Box2DV3Sim
from .figures_cases import CASE_FIGURES
from .figures_samples import SAMPLE_FIGURES

RESULTS = Path(__file__).resolve().parents[1] / "results"
CONDITIONS = {"dt": 1 / 60, "substeps": 4, "sleeping": False, "threads": 1, "continuous": True}


def run_scene(name, seconds, substeps=4, scene_kw=None):
    """(trace, description, sim) of a sample run for ``seconds`` in Box2D v3."""
    desc = SAMPLES[name](**(scene_kw or {}))
    sim = Box2DV3Sim(desc, threads=1, substeps=substeps, sleeping=False)
    names = {k: v[0] for k, v in sim.names.items() if isinstance(k, str)}
    return M.record(sim, seconds, names), desc, sim


def measure(only=None):
    """All figures (list of dicts), optionally only those whose function name contains ``only``."""
    funcs = [f for f in SAMPLE_FIGURES + CASE_FIGURES if not only or only in f.__name__]
    figs = []
    for f in tqdm(funcs, desc="box2d figures", file=sys.stderr):
        t0 = time.perf_counter()
        for fig in f(run_scene):
            d = asdict(fig)
            d["measured_by"] = f"bench/box2d/{'figures_samples' if f in SAMPLE_FIGURES else 'figures_cases'}.py " \
                               f"{f.__name__}"
            d["wall_s"] = round(time.perf_counter() - t0, 2)
            figs.append(d)
    return figs


def _fmt(v):
    if isinstance(v, bool) or v is None:
        return str(v)
    if isinstance(v, int):
        return str(v)
    return f"{v:.4g}"


def write(figs, out):
    """``out.json`` (every figure with its definition) and ``out.md`` (a table)."""
    b = B.build()
    meta = {"engine": "Box2D v3", "snapshot": b.snapshot, "source": str(b.source),
            "date": datetime.now(timezone.utc).isoformat(timespec="seconds"), "conditions": CONDITIONS,
            "how": "python -m bench.box2d.samples: scene descriptions of bench/suite (samples.py) run through "
                   "bench/box2d (Box2DV3Sim, our C shim over the snapshot built Release); quantities from "
                   "bench/suite/measures.py on the recorded per-step states"}
    out.with_suffix(".json").write_text(json.dumps({"meta": meta, "figures": figs}, indent=1, default=float))
    lines = [f"# Box2D v3 figures ({b.snapshot[:12]})", "",
             f"Measured {meta['date']} with `python -m bench.box2d.samples`: dt 1/60, 4 sub-steps, sleeping off, "
             "one thread, Box2D defaults or the sample's own tuning. Definitions in full (body, window, quantity) "
             "are in `box2d_v3_figures.json`; scenes in `bench/suite/`.", "",
             "| figure | value | unit | definition |", "|---|---|---|---|"]
    for f in figs:
        ref = f.get("reference", {})
        extra = ""
        for key in ("ideal", "issue_18_quotes", "issue_14_quotes", "issue_18_target"):
            if key in ref:
                extra += f" ({key.replace('_', ' ')}: {_fmt(ref[key]) if not isinstance(ref[key], str) else ref[key]})"
        text = (f["definition"] + extra).replace("|", "\\|")  # a literal bar inside a table cell
        lines.append(f"| `{f['id']}` | {_fmt(f['value'])} | {f['unit']} | {text} |")
    out.with_suffix(".md").write_text("\n".join(lines) + "\n")


def main(argv=None):
    ap = argparse.ArgumentParser(description="Box2D v3 figures on its samples and the issue 14/18 cases")
    ap.add_argument("--only", help="only figure functions whose name contains this (e.g. card_house)")
    ap.add_argument("--out", default=str(RESULTS / "box2d_v3_figures"))
    a = ap.parse_args(argv)
    if not B.available():
        print(f"Box2D v3 unavailable: {B.why_unavailable()}", file=sys.stderr)
        return 1
    figs = measure(a.only)
    write(figs, Path(a.out))
    for f in figs:
        print(f"{f['id']:55s} {_fmt(f['value']):>12s} {f['unit']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
