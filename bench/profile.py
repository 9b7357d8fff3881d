"""Where a step's time goes: each pipeline stage timed in place.

    python -m bench.profile [--scene pyramid20|pyramid40|rain] [--solver soft_step] [--steps 300]

The world steps normally (``world.step()``); the stage entry points the
pipeline calls -- ``Pipeline.refresh_geometry``, ``broadphase.find_pairs``,
``narrowphase.collide``, the mode's ``step``, ``Pipeline.sleep`` and the
checkpoint's save / finite check -- are wrapped with timers for the run, so
the breakdown follows whatever the pipeline does.  "python/other" is the
step's wall time not inside any stage (Python glue in ``World.step`` and
``Pipeline.step``, zeroing force arrays, bookkeeping).
"""
from __future__ import annotations

import argparse
import contextlib
import time

import numpy as np

STAGES = ("checkpoint+geometry", "broadphase", "narrowphase", "solver", "sleep/islands", "finite_check")


@contextlib.contextmanager
def _patched(world, acc):
    from physics import broadphase, narrowphase
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

    from physics import pipeline as pipeline_module
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


def stage_profile(world, steps=200, warm=30, chunk=20):
    """Microseconds per step in each stage of ``world.step()`` (after ``warm`` steps), from the
    chunk of ``chunk`` steps with the smallest total: load from other processes on a shared
    machine only ever adds time, so the fastest chunk is the best estimate of the step itself."""
    for _ in range(warm):
        world.step()
    per_chunk = []
    for _ in range(max(1, steps // chunk)):
        acc = {s: 0.0 for s in STAGES}
        with _patched(world, acc):
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


def call_overhead(reps=20000):
    """Cost of calling a compiled kernel from Python with the core's argument types: one array, the
    bodies table (a namedtuple of arrays) and the contact table.  Numba unboxes every array of a
    namedtuple on every call, so each table argument costs microseconds before any work is done."""
    import physics
    from numba import njit

    @njit
    def touch(a, n):
        return n

    w = physics.World()
    w.add_body(physics.Polygon.box(1, 1))
    w.step()
    args = {"one array": w._bodies.view.x, "bodies table": w._bodies.view, "contacts table": w._contacts.cur,
            "springs table": w._springs.view, "vertex pool": w._verts.view}
    out = {}
    for name, a in args.items():
        touch(a, 1)
        best = np.inf
        for _ in range(3):
            t = time.perf_counter()
            for _ in range(reps):
                touch(a, 1)
            best = min(best, (time.perf_counter() - t) / reps)
        fields = len(a) if isinstance(a, tuple) else 1
        out[name] = {"us_per_call": 1e6 * best, "arrays": fields}
    return out


def narrowphase_per_pair(prof):
    pairs = max(prof["pairs"], 1)
    return 1e3 * prof["us_per_step"]["narrowphase"] / pairs  # ns per pair


def format_profile(name, prof):
    us = prof["us_per_step"]
    tot = us["total"]
    lines = [f"{name}: {tot / 1e3:.3f} ms/step (fastest chunk), {prof['bodies']} bodies, {prof['pairs']} broad-phase pairs, "
             f"{prof['contacts']} manifolds"]
    for s in (*STAGES, "python/other"):
        lines.append(f"  {s:<14} {us[s]:9.1f} us  {100 * us[s] / tot:5.1f} %")
    lines.append(f"  narrow phase per pair: {narrowphase_per_pair(prof):.0f} ns")
    return "\n".join(lines)


def main(argv=None):
    from . import run
    ap = argparse.ArgumentParser(prog="python -m bench.profile", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scene", default="pyramid20", choices=list(run.SCENES))
    ap.add_argument("--solver", default="soft_step")
    ap.add_argument("--steps", type=int, default=300)
    a = ap.parse_args(argv)
    desc, src = run.scene_desc(a.scene)
    sim = run.make_ours(a.scene, desc, src, a.solver, {})
    sim.step()
    print(format_profile(f"{a.scene} [{a.solver}]", stage_profile(sim.world, a.steps)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
