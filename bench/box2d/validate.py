"""Check the shim against Box2D's own ``benchmark`` app: same scene, same ms/step within noise.

For each suite scene and worker count, runs alternate (interleaved, so that the machine's load
hits both alike): Box2D's app (``benchmark -t=T -w=T -b=NAME -r=1``: it builds the scene with
``benchmarks.c``) and our shim on the scene description of ``bench/suite`` (built through
Python, stepped through ctypes one ``sim.step()`` at a time). Both time the same thing, as the
app does: the scene's step count minus the first step, events and drives included.

    python -m bench.box2d.validate [--scenes a,b] [--threads 1,2] [--repeats 3] [--out PATH]

Writes ``bench/results/box2d_v3_validation.{json,md}``: per scene and thread count the min and
median ms/step of each side and the median of the per-pair ratios shim / app.
"""
from __future__ import annotations

import argparse
import json
import re
import statistics
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timezone
from pathlib import Path

from tqdm import tqdm

from ..suite import SUITE
from . import build as B
from .engine import Box2DV3Sim

RESULTS = Path(__file__).resolve().parents[1] / "results"


def app_run(benchmark, name, threads, cwd):
    """ms for one run of Box2D's benchmark app on ``name`` with ``threads`` workers (its own scheduler)."""
    out = subprocess.run([str(benchmark), f"-t={threads}", f"-w={threads}", f"-b={name}", "-r=1"], cwd=cwd,
                         capture_output=True, text=True, timeout=1800)
    if out.returncode != 0:
        raise RuntimeError(f"benchmark app failed on {name}: {out.stdout[-500:]}{out.stderr[-500:]}")
    m = re.findall(r"run 0 : ([0-9.eE+-]+) \(ms\)", out.stdout)
    c = re.search(r"body (\d+) / shape (\d+) / contact (\d+) / joint (\d+)", out.stdout)
    if not m or not c:
        raise RuntimeError(f"no timing in the benchmark app's output for {name}: {out.stdout[-500:]}")
    return float(m[-1]), dict(zip(("bodies", "shapes", "contacts", "joints"), map(int, c.groups())))


def shim_run(desc, threads, scheduler):
    """ms for the same protocol through ``Box2DV3Sim`` (first step untimed, then steps 1..N-1)."""
    steps = int(desc["bench"]["steps"])
    sim = Box2DV3Sim(desc, threads=threads, substeps=4, sleeping=None, scheduler=scheduler, track_angles=False)
    sim.step()
    t0 = time.perf_counter()
    for _ in range(steps - 1):
        sim.step()
    ms = (time.perf_counter() - t0) * 1e3
    counters = sim.counters()  # bodies include the shim's own empty ground (joints to the world)
    sim.close()
    return ms, {k: counters[k] for k in ("bodies", "shapes", "contacts", "joints")}


def validate(scenes, threads_list, repeats, schedulers=("shim", "box2d")):
    """Interleaved app / shim timings; returns a list of result rows (dicts)."""
    b = B.build()
    rows = []
    total = len(scenes) * sum(1 + (len(schedulers) if t > 1 else 1) for t in threads_list) * repeats
    bar = tqdm(total=total, desc="box2d validate", file=sys.stderr)
    with tempfile.TemporaryDirectory() as tmp:
        for name in scenes:
            desc = SUITE[name]()
            steps = int(desc["bench"]["steps"])
            for t in threads_list:
                scheds = schedulers if t > 1 else ("serial",)
                app, ours, counts = [], {s: [] for s in scheds}, {}
                for _ in range(repeats):
                    ms, counts["app"] = app_run(b.benchmark, name, t, tmp)
                    app.append(ms / (steps - 1))
                    bar.update()
                    for s in scheds:
                        ms, counts[s] = shim_run(desc, t, s)
                        ours[s].append(ms / (steps - 1))
                        bar.update()
                for s in scheds:
                    ratios = [o / a for o, a in zip(ours[s], app)]
                    rows.append({"scene": name, "threads": t, "scheduler": s, "steps": steps,
                                 "app_ms_per_step": app, "shim_ms_per_step": ours[s],
                                 "app_min": min(app), "shim_min": min(ours[s]),
                                 "app_median": statistics.median(app), "shim_median": statistics.median(ours[s]),
                                 "ratio_median": statistics.median(ratios), "ratio_of_mins": min(ours[s]) / min(app),
                                 "app_counts_at_end": counts["app"], "shim_counts_at_end": counts[s]})
    bar.close()
    return rows, b


def write(rows, b, out_json, out_md, repeats):
    """JSON with every run, and a readable table."""
    meta = {"snapshot": b.snapshot, "date": datetime.now(timezone.utc).isoformat(timespec="seconds"),
            "machine": "2 cores shared with other processes (load varies; ratios are of interleaved runs)",
            "protocol": "Box2D benchmark app -t=T -w=T -b=NAME -r=1, alternated with Box2DV3Sim on the bench/suite "
                        "description (threads=T, 4 sub-steps, world sleeping as the scene says), repeats=%d; "
                        "ms over steps 1..N-1 divided by N-1" % repeats}
    out_json.write_text(json.dumps({"meta": meta, "rows": rows}, indent=1))
    lines = [f"# Box2D v3 shim vs Box2D's benchmark app ({b.snapshot[:12]})", "", meta["protocol"] + ".", "",
             "Counts at the end (bodies / shapes / joints / contacts): the app's and the shim's. Shapes and joints",
             "must agree exactly (same scene) and bodies too, but for empty ground bodies: the shim always has one",
             "(for joints attached to the world), the app only where benchmarks.c makes one (tumbler, washer);",
             "contacts agree within the scene's chaos (float rounding of the initial positions differs).", "",
             "| scene | threads | shim scheduler | app ms/step (min) | shim ms/step (min) | ratio (median of pairs) "
             "| app counts | shim counts |", "|---|---|---|---|---|---|---|---|"]

    def fmt(c):
        return f"{c['bodies']} / {c['shapes']} / {c['joints']} / {c['contacts']}"
    for r in rows:
        lines.append(f"| {r['scene']} | {r['threads']} | {r['scheduler']} | {r['app_min']:.3f} | {r['shim_min']:.3f} "
                     f"| {r['ratio_median']:.3f} | {fmt(r['app_counts_at_end'])} | {fmt(r['shim_counts_at_end'])} |")
    lines += ["", "Median over scenes of the per-scene ratios: " + ", ".join(
        f"{t} thread(s) {s}: {statistics.median(r['ratio_median'] for r in rows if (r['threads'], r['scheduler']) == (t, s)):.3f}"
        for t, s in dict.fromkeys((r["threads"], r["scheduler"]) for r in rows)) + ".",
        "", "The machine: " + meta["machine"] + "."]
    out_md.write_text("\n".join(lines) + "\n")


def main(argv=None):
    ap = argparse.ArgumentParser(description="shim vs Box2D benchmark app, interleaved")
    ap.add_argument("--scenes", default=",".join(SUITE))
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--out", default=str(RESULTS / "box2d_v3_validation"))
    a = ap.parse_args(argv)
    if not B.available():
        print(f"Box2D v3 unavailable: {B.why_unavailable()}", file=sys.stderr)
        return 1
    scenes = [s for s in a.scenes.split(",") if s]
    rows, b = validate(scenes, [int(t) for t in a.threads.split(",")], a.repeats)
    out = Path(a.out)
    write(rows, b, out.with_suffix(".json"), out.with_suffix(".md"), a.repeats)
    print(out.with_suffix(".md").read_text())
    return 0


if __name__ == "__main__":
    sys.exit(main())
