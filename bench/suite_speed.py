"""Box2D v3's own benchmark suite, timed side by side: ``python -m bench.suite_speed``.

Every scene of ``bench.suite.SUITE`` (``shared/benchmarks.c`` rebuilt as scene descriptions)
that Stelkropp can build runs in Stelkropp (soft_step defaults) with one thread and with two
(``World.threads``), Box2D v3 with one thread and with two, and pymunk where its adapter can
build the scene, interleaved chunk by chunk exactly
as ``python -m bench`` times its own scenes (bench/timing.py): ms/step is the median over the
timed chunks, a ratio the median of the per-chunk ratios, the first step (compile) apart.
A scene's ``bench`` script (rain's ragdoll events, junkyard's pusher drive) runs on our side
too (bench/suite/scripts.py), as Box2D's side runs it; pymunk's adapter has no scripts and sits
those scenes out. A scene an engine cannot build is reported with the reason, never silently
dropped; ``bench.suite.NEEDS`` says how each scene still differs from Box2D's.

    python -m bench.suite_speed                          # every scene, the suite's step counts
    python -m bench.suite_speed --scenes large_pyramid --steps 200 --out /tmp/suite

Writes ``box2d_suite.json``, ``box2d_suite.md`` and ``box2d_suite.png`` into ``--out``
(default bench/results/); ``python -m bench --docs-only`` puts the table into docs/benchmarks.md.
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from .engines import build, why_unusable
from .engines.ours import OursSim
from .paths import RESULTS
from .report.suite_table import B1, B2, OURS, OURS2, PM, table_md
from .suite import NEEDS, SUITE
from .suite.common import strip_box2d
from .suite.scripts import Scripted, sleep_threshold
from .timing import chunk_ratio, interleaved, median_ms

def _ours(desc, settings=None, threads=1):
    """Stelkropp's world from the scene loader (it refuses what the core lacks, e.g. joints before
    the joints issue lands, instead of building a different scene), behind OursSim; ``settings``:
    soft_step settings instead of their defaults (``--set``)."""
    from physics.scene import scene_from_dict
    data = strip_box2d(desc)
    data.pop("bench", None)
    try:
        world = scene_from_dict(data, source=f"bench.suite {desc.get('name')}")
    except Exception:
        if data.get("joints") or any("shapes" in b for b in data["bodies"]):
            raise
        world = None  # a loader without version 2: the scene uses only version-1 bodies
    sim = OursSim(desc, world=world)
    sim.world.solver = "soft_step"
    sim.world.settings.update(settings or {})
    sim.world.threads = threads
    if (v := sleep_threshold(desc)) is not None:
        sim.world.sleep_linear = v  # Box2D's per-body sleepThreshold, the same on every body (rain)
    bench = desc.get("bench", {})
    return Scripted(sim, desc) if bench.get("events") or bench.get("drives") else sim


def _pymunk(desc):
    """pymunk's adapter, refusing a scene with a script: it would time another scene."""
    bench = desc.get("bench", {})
    if bench.get("events") or bench.get("drives"):
        raise NotImplementedError("the pymunk adapter does not run bench.events / bench.drives")
    return build("pymunk", desc)


def _sims(desc, settings=None):
    """{label: Sim} of every engine that builds ``desc``, and {label: why not} for the others."""
    makers = {OURS: lambda: _ours(desc, settings),
              OURS2: lambda: _ours(desc, settings, threads=2),
              B1: lambda: build("box2d_v3", desc, threads=1, sleeping=None, track_angles=False),
              B2: lambda: build("box2d_v3", desc, threads=2, sleeping=None, track_angles=False),
              PM: lambda: _pymunk(desc)}
    sims, why = {}, {}
    for label, make in makers.items():
        try:
            sims[label] = make()
        except Exception as exc:  # an unsupported shape or joint: say which, time the rest
            why[label] = f"{type(exc).__name__}: {str(exc)[:160]}"
    return sims, why


def run_scene(name, steps=None, chunk=10, warm=20, budget_s=None, desc=None, settings=None) -> dict:
    """One suite scene timed in every engine that builds it; a row dict (ms/step, ratios).
    ``desc``: the scene built with other parameters (tests: smaller), default ``SUITE[name]()``;
    ``settings``: soft_step settings of ours instead of the defaults."""
    desc = desc if desc is not None else SUITE[name]()
    n = int(steps or desc.get("bench", {}).get("steps", 300))
    if desc.get("bench", {}).get("events"):  # a short run: the events it reaches (both sides pre-translate them)
        desc = {**desc, "bench": {**desc["bench"], "events": [e for e in desc["bench"]["events"] if e["step"] < n]}}
    row = {"scene": name, "bodies": len(desc["bodies"]), "steps": n, "needs": NEEDS.get(name, []),
           "suite_steps": desc.get("bench", {}).get("steps"),
           "source": desc.get("bench", {}).get("source")}
    sims, why = _sims(desc, settings)
    row["not_built"] = why
    if OURS not in sims:
        row["status"] = "stelkropp cannot build it yet"
        return row
    first, chunks, done, err = interleaved(sims, n, chunk, warm, budget_s)
    row.update(steps_done=done, status=err or "ok",
               first_step_s={k: round(v, 3) for k, v in first.items()},
               ms_step={k: median_ms(c) for k, c in chunks.items()})
    row["bodies_end"] = len(sims[OURS].world.bodies)  # rain: the ragdolls its events added
    row["ratio"] = {k: chunk_ratio(chunks[OURS], c) for k, c in chunks.items() if k != OURS}
    if OURS2 in chunks:
        row["ratio_2t"] = {k: chunk_ratio(chunks[OURS2], chunks[k]) for k in (B1, B2) if k in chunks}
        row["two_thread_speedup"] = chunk_ratio(chunks[OURS], chunks[OURS2])
    if B1 in chunks and B2 in chunks:
        row["box2d_two_thread_speedup"] = chunk_ratio(chunks[B1], chunks[B2])
    return row


def plot(rows, path):
    """Bar chart of ms/step per scene and engine (log scale)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    done = [r for r in rows if r.get("ms_step")]
    if not done:
        return None
    fig, ax = plt.subplots(figsize=(max(6, 1.6 * len(done)), 4.5))
    engines = [OURS, OURS2, B1, B2, PM]
    x = np.arange(len(done))
    for i, e in enumerate(engines):
        ys = [r["ms_step"].get(e) or np.nan for r in done]
        ax.bar(x + (i - 2) * 0.16, ys, 0.16, label=e)
    ax.set_xticks(x, [r["scene"] for r in done])
    ax.set_yscale("log")
    ax.set_ylabel("ms/step (median of interleaved chunks)")
    ax.set_title("Box2D v3's benchmark suite (shared/benchmarks.c)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main(argv=None) -> int:
    """``python -m bench.suite_speed``; returns 0, or 1 when Box2D v3 cannot run here."""
    ap = argparse.ArgumentParser(prog="python -m bench.suite_speed", description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", default=",".join(SUITE), help=f"comma-separated, from {', '.join(SUITE)}")
    ap.add_argument("--steps", type=int, default=None, help="steps per scene (default: the suite's own counts)")
    ap.add_argument("--budget", type=float, default=None, help="seconds per scene before it is cut")
    ap.add_argument("--out", type=Path, default=RESULTS)
    ap.add_argument("--set", action="append", metavar="NAME=VALUE", dest="settings",
                    help="a soft_step setting of ours instead of its default (repeatable; the table is "
                         "printed, not written)")
    a = ap.parse_args(argv)
    from .reliability.samples import parse_settings
    try:
        settings = parse_settings(a.settings)
    except ValueError as err:
        ap.error(str(err))
    names = a.scenes.split(",")
    bad = [n for n in names if n not in SUITE]
    if bad:
        ap.error(f"unknown scene: {', '.join(bad)} (known: {', '.join(SUITE)})")
    why = why_unusable("box2d_v3")
    if why:
        print(f"Box2D v3 cannot run here: {why}", file=sys.stderr)
        return 1
    from tqdm import tqdm
    rows = []
    for name in (bar := tqdm(names, unit="scene", file=sys.stderr)):
        bar.set_description(name)
        rows.append(run_scene(name, a.steps, budget_s=a.budget, settings=settings))
    md = table_md(rows)
    if settings:  # not the default mode: the recorded results stay the defaults'
        print(f"soft_step settings: {settings}")
        print("\n".join(md))
        return 0
    a.out.mkdir(parents=True, exist_ok=True)
    (a.out / "box2d_suite.json").write_text(json.dumps(rows, indent=1, default=float))
    (a.out / "box2d_suite.md").write_text("\n".join(md) + "\n")
    plot(rows, a.out / "box2d_suite.png")
    print("\n".join(md))
    return 0


if __name__ == "__main__":
    sys.exit(main())
