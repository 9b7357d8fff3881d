"""Where a step's time goes: the core's own per-stage timings (``world.profile``), per scene.

    python -m bench.profile [--scene pyramid20|pyramid40|rain1000] [--solver soft_step] [--steps 300]

``world.profile`` holds the seconds of every pipeline stage of the last step (like Box2D's
b2Profile) and their sum (``step``).  The world steps normally; each ``world.step()`` call is
timed and its profile added up outside the timed call.  "python/other" is the wall time of
``world.step()`` outside every stage (argument checks and glue in ``World.step``).
"""
from __future__ import annotations

import argparse
import time

import numpy as np

TOTAL = "step"  # world.profile's sum of its stages
# the stages of results measured before the core timed its own stages (timers were wrapped around
# the pipeline's entry points): kept so that --docs-only renders older bench.json files
LEGACY_STAGES = ("checkpoint+geometry", "broadphase", "narrowphase", "solver", "sleep/islands", "finite_check")


def stage_names(world) -> list[str]:
    """The stage names ``world.profile`` reports, in pipeline order (without their sum)."""
    return [k for k in world.profile if k != TOTAL]


def result_stages(prof) -> list[str]:
    """The stage names of a ``stage_profile`` result (older results: LEGACY_STAGES)."""
    return list(prof.get("stage_names") or LEGACY_STAGES)


def _chunk(world, names, chunk):
    """Seconds per stage and the wall time of ``chunk`` steps."""
    acc = dict.fromkeys(names, 0.0)
    total = 0.0
    clock = time.perf_counter
    for _ in range(chunk):
        t = clock()
        world.step()
        total += clock() - t
        prof = world.profile
        for s in names:
            acc[s] += prof[s]
    acc["total"] = total
    return acc


def stage_profile(world, steps=200, warm=30, chunk=20) -> dict:
    """Microseconds per step in each stage of ``world.step()`` (after ``warm`` steps), from the
    chunk of ``chunk`` steps with the smallest wall time: load from other processes on a shared
    machine only ever adds time, so the fastest chunk is the best estimate of the step itself.

    Returns {"us_per_step": {stage: us, "total", "python/other", "median_total"}, "stage_names",
    "contacts", "bodies", "pairs", "stages"}."""
    for _ in range(warm):
        world.step()
    names = stage_names(world)
    per_chunk = [{k: 1e6 * v / chunk for k, v in _chunk(world, names, chunk).items()}
                 for _ in range(max(1, steps // chunk))]
    best = min(per_chunk, key=lambda c: c["total"])
    out = {k: float(best[k]) for k in (*names, "total")}
    out["python/other"] = max(out["total"] - sum(out[s] for s in names), 0.0)
    out["median_total"] = float(np.median([c["total"] for c in per_chunk]))
    info = world.info()
    # the broad phase's pair count has no public accessor: read from the pipeline when it has one
    pairs = getattr(getattr(world, "_pipeline", None), "npairs", 0)
    return {"us_per_step": out, "stage_names": names, "contacts": int(info.get("contacts", 0)),
            "bodies": int(info.get("bodies", 0)), "pairs": int(pairs), "stages": info.get("stages", [])}


def narrowphase_per_pair(prof) -> float:
    """Narrow-phase nanoseconds per broad-phase pair of a ``stage_profile`` result."""
    pairs = max(prof["pairs"], 1)
    return 1e3 * prof["us_per_step"]["narrowphase"] / pairs


def format_profile(name, prof) -> str:
    """A ``stage_profile`` result as text lines (one per stage, us and share of the step)."""
    us = prof["us_per_step"]
    tot = us["total"]
    lines = [f"{name}: {tot / 1e3:.3f} ms/step (fastest chunk), {prof['bodies']} bodies, {prof['pairs']} broad-phase pairs, "
             f"{prof['contacts']} manifolds"]
    for s in (*result_stages(prof), "python/other"):
        lines.append(f"  {s:<14} {us[s]:9.1f} us  {100 * us[s] / tot:5.1f} %")
    lines.append(f"  narrow phase per pair: {narrowphase_per_pair(prof):.0f} ns")
    return "\n".join(lines)


def profile_scene(key, mode, steps, warm) -> dict:
    """``stage_profile`` of benchmark scene ``key`` (bench/scenes.py) in ``mode``, default settings."""
    from .configs import Config
    from .scenes import scene_data
    from .speed import make_ours
    sim = make_ours(scene_data(key), Config(mode, {}, mode, default=True))
    sim.step()
    return stage_profile(sim.world, steps=steps, warm=warm)


def main(argv=None) -> int:
    """``python -m bench.profile``: print one scene's stage breakdown."""
    from .scenes import SCENES
    ap = argparse.ArgumentParser(prog="python -m bench.profile", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scene", default="pyramid20", choices=list(SCENES))
    ap.add_argument("--solver", default="soft_step")
    ap.add_argument("--steps", type=int, default=300)
    a = ap.parse_args(argv)
    print(format_profile(f"{a.scene} [{a.solver}]", profile_scene(a.scene, a.solver, a.steps, warm=30)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
