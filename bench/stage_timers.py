"""Stage timers put around the pipeline's entry points while ``world.step()`` runs: the profile
of a core that does not report ``world.profile`` itself.

The stage entry points the pipeline calls -- ``begin_step`` / ``end_step`` (or, in older
pipelines, ``Pipeline.refresh_geometry`` and the checkpoint's save / finite check),
``broadphase.find_pairs``, ``narrowphase.collide``, the mode's ``step`` and ``Pipeline.sleep``
-- are wrapped with timers for the block and put back afterwards, so the breakdown follows
whatever the pipeline does.  This reaches into the world's private pipeline; it goes when the
core reports the same figures itself (``world.profile``, issue 12).
"""
from __future__ import annotations

import contextlib
import time

import numpy as np

STAGES = ("checkpoint+geometry", "broadphase", "narrowphase", "solver", "sleep/islands", "finite_check")


@contextlib.contextmanager
def timed_stages(world, acc):
    """While the block runs, every stage entry point the pipeline calls adds its wall time
    (seconds) to ``acc[stage]`` (``acc`` must hold every name of STAGES); undone on exit."""
    from physics.collision import broadphase, narrowphase
    pipe = world._pipeline
    mode = world._mode
    clock = time.perf_counter
    undo = []

    def wrap(obj, attr, stage):
        orig = getattr(obj, attr)

        def timed(*a, **k):
            t = clock()
            try:
                return orig(*a, **k)
            finally:
                acc[stage] += clock() - t
        setattr(obj, attr, timed)
        undo.append((obj, attr, orig, attr in vars(obj)))

    from physics.step import pipeline as pipeline_module
    # the step opens with one kernel (checkpoint + geometry) and closes with one (finite check +
    # force reset) where the pipeline has them; older pipelines call the pieces separately
    if hasattr(pipeline_module, "begin_step"):
        wrap(pipeline_module, "begin_step", "checkpoint+geometry")
        wrap(pipeline_module, "end_step", "finite_check")
    else:
        wrap(pipe, "refresh_geometry", "checkpoint+geometry")
        cp = pipe._checkpoint
        if hasattr(cp, "save"):
            wrap(cp, "save", "checkpoint+geometry")
        if hasattr(cp, "nonfinite"):
            wrap(cp, "nonfinite", "finite_check")
    wrap(broadphase, "find_pairs", "broadphase")
    wrap(narrowphase, "collide", "narrowphase")
    wrap(mode, "step", "solver")
    wrap(pipe, "sleep", "sleep/islands")
    try:
        yield
    finally:
        for obj, attr, orig, own in reversed(undo):
            if own:  # a module function or an instance's own attribute: put it back
                setattr(obj, attr, orig)
            else:  # the wrapper shadowed a class method: remove the shadow
                delattr(obj, attr)


def stage_profile(world, steps=200, warm=30, chunk=20) -> dict:
    """``bench.profile.stage_profile`` measured with the stage timers (same result layout; the
    stage names are STAGES)."""
    for _ in range(warm):
        world.step()
    per_chunk = []
    for _ in range(max(1, steps // chunk)):
        acc = {s: 0.0 for s in STAGES}
        with timed_stages(world, acc):
            t = time.perf_counter()
            for _ in range(chunk):
                world.step()
            total = time.perf_counter() - t
        acc["total"] = total
        per_chunk.append({k: 1e6 * v / chunk for k, v in acc.items()})
    # the least-disturbed chunk (smallest total) on a shared machine; the median total is kept beside it
    best = min(per_chunk, key=lambda c: c["total"])
    out = {k: float(best[k]) for k in (*STAGES, "total")}
    out["python/other"] = max(out["total"] - sum(out[s] for s in STAGES), 0.0)
    out["median_total"] = float(np.median([c["total"] for c in per_chunk]))
    info = world.info()
    return {"us_per_step": out, "contacts": int(info.get("contacts", 0)), "bodies": int(info.get("bodies", 0)),
            "pairs": int(getattr(world._pipeline, "npairs", 0)), "stages": info.get("stages", [])}
