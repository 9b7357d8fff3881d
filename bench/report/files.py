"""The run's files: bench.json, speed/scaling/accuracy/profile CSVs, plots; the run's metadata."""
from __future__ import annotations

import csv
import datetime
import json
import os
import platform
import subprocess
from pathlib import Path

import numpy as np

from .. import plots
from ..paths import ROOT


def write_csv(path, rows, keys=None):
    """``rows`` (dicts) as CSV with columns ``keys`` (default: every key, sorted); nothing for no rows."""
    if not rows:
        return
    keys = keys or sorted({k for r in rows for k in r})
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: json.dumps(v) if isinstance(v, (dict, list)) else v for k, v in r.items()})


def write_outputs(res, outdir):
    """bench.json, the CSVs and the plots of ``res`` into ``outdir``; returns the PNG paths."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    with open(outdir / "bench.json", "w") as f:
        json.dump(res, f, indent=1, default=float)
    write_csv(outdir / "speed.csv", res.get("speed", []),
         ["scene", "engine", "mode", "label", "settings", "default", "ms_step", "ms_step_min", "ratio_pymunk",
          "ratio_pybox2d", "ratio_box2d_v3", "error", "top_drift", "max_penetration", "mean_penetration", "escaped", "steps",
          "sim_time", "chunks", "first_step_s", "status", "source"])
    write_csv(outdir / "scaling.csv", res.get("scaling", []),
         ["n", "engine", "mode", "ms_step", "ratio_pymunk", "ratio_pybox2d", "ratio_box2d_v3", "contacts", "chunks", "status"])
    write_csv(outdir / "accuracy.csv", res.get("accuracy", []),
         ["engine", "mode", "label", "settings", "dt", "integrator", "scenario", "metric", "value", "expected",
          "error", "unit", "default", "note"])
    prof = []
    for scene, p in (res.get("profile") or {}).items():
        for stage, us in p["us_per_step"].items():
            prof.append(dict(scene=scene, stage=stage, us_per_step=us,
                             share=us / p["us_per_step"]["total"] if p["us_per_step"]["total"] else None))
    write_csv(outdir / "profile.csv", prof, ["scene", "stage", "us_per_step", "share"])
    return plots.make_all(res, outdir)


def _git_commit():
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                              text=True, timeout=10).stdout.strip()
    except Exception:
        return ""


def meta(quick) -> dict:
    """Date, commit, machine and library versions of this run."""
    import numba
    import pymunk
    import Box2D
    return dict(date=datetime.datetime.now().isoformat(timespec="seconds"), quick=quick, commit=_git_commit(),
                python=platform.python_version(), numpy=np.__version__, numba=numba.__version__,
                pymunk=pymunk.version, pybox2d=getattr(Box2D, "__version__", "2.3"), machine=platform.machine(),
                cpus=os.cpu_count(), platform=platform.platform())
