"""The benchmark suite: scenes x solver modes x settings, beside pymunk and pybox2d.

    python -m bench                 # full run (< 20 min on 2 cores): results, plots, table
    python -m bench --quick         # CI smoke (< 2 min): defaults only, short runs
    python -m bench --write-docs    # full run, then rewrite docs/benchmarks.md
    python -m bench --docs-only     # re-plot and rewrite the docs from bench/results/bench.json

Speed: every configuration runs its scene in chunks of steps, interleaved chunk by
chunk with pymunk and pybox2d on the identical scene (ours, pymunk, pybox2d, ours,
...), after warm-up chunks that are not timed; ms/step is the median over the timed
chunks and the ratio to a reference is the median of the per-chunk ratios, so
machine noise that hits all three engines cancels.  The first step (numba compile
or cache load) is timed apart and never enters ms/step.
"""
from __future__ import annotations

import argparse
import csv
import dataclasses
import datetime
import gc
import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from . import accuracy, refs

RESULTS = Path(__file__).resolve().parent / "results"
DOCS = refs.ROOT / "docs" / "benchmarks.md"
REF_ENGINES = ("pymunk", "pybox2d")
DEFAULT_MODE = "soft_step"
QUICK_MODES = ("soft_step", "sequential_impulse")

# Box2D v3.2 (C, SIMD, graph colouring; not on PyPI) on this machine, from
# ../shared/PLATFORM_NOTES.md: ms/step and pymunk's figure measured with it.
BOX2D_V3 = {"pyramid20": ((0.08, 0.10), 0.31), "pyramid40": ((0.33, 0.44), 1.30), "rain1000": ((0.19, 0.24), 1.28)}

# -- scenes --------------------------------------------------------------------------------
BENCH_WORLD = {"gravity": [0.0, -10.0], "dt": 1 / 60, "sleeping": False}
SCENES = {
    # key: (scene file or None, generator, error metric, full plan, quick plan, sweep settings)
    "pyramid20": dict(file="pyramid.json", gen=lambda: refs.pyramid(20), error="top_drift",
                      full=dict(steps=600, chunk=30, warm=60), quick=dict(steps=180, chunk=20, warm=40), sweep=True,
                      title="Pyramid, base 20 (210 boxes)"),
    "pyramid40": dict(file="pyramid_large.json", gen=lambda: refs.pyramid(40), error="top_drift",
                      full=dict(steps=600, chunk=30, warm=60), quick=None, sweep=True,
                      title="Pyramid, base 40 (820 boxes)"),
    "rain1000": dict(file=None, gen=lambda: refs.rain(1000), error="max_penetration",
                     full=dict(steps=720, chunk=30, warm=120), quick=dict(steps=140, chunk=20, warm=80), sweep=True,
                     title="Rain: 1000 boxes (1x1) into a 40 m container"),
    "rain_mixed": dict(file="rain.json", gen=None, error="max_penetration", keep_world=True,
                       full=dict(steps=480, chunk=30, warm=120), quick=None, sweep=False,
                       title="scenes/rain.json: 1000 mixed convex shapes (defaults only)"),
}
ERROR_LABEL = {"top_drift": "top-box drift after the run (m)", "max_penetration": "max penetration at the end (m)"}


def scene_desc(key):
    """(description, source) -- the shipped scene file when there is one, else generated."""
    sc = SCENES[key]
    path = refs.SCENES / sc["file"] if sc["file"] else None
    if path is not None and path.exists():
        desc, src = refs.load_desc(path), str(path.relative_to(refs.ROOT))
    elif sc["gen"] is not None:
        desc, src = sc["gen"](), "generated (bench/refs.py)"
    else:
        return None, None
    world = {"sleeping": False} if sc.get("keep_world") else BENCH_WORLD
    return refs.with_world(desc, **world), src


def make_ours(key, desc, src, solver, settings, integrator=None):
    world = None
    if src and src.endswith(".json"):
        try:
            import physics
            world = physics.load_scene(refs.ROOT / src)
            if world._bodies.n != len(desc["bodies"]):
                world = None
        except Exception:  # the loader is another module's job; the same dict builds the same world
            world = None
    return refs.OursSim(desc, solver=solver, settings=settings, world=world, integrator=integrator)


# -- configurations -------------------------------------------------------------------------
@dataclasses.dataclass
class Config:
    mode: str
    settings: dict
    label: str
    default: bool = False
    integrator: str | None = None


SWEEPS = {
    "soft_step": [{"substeps": 1}, {"substeps": 2}, {"substeps": 8}, {"iterations": 2}, {"relax": False},
                  {"warm_starting": False}, {"block_solver": False}],
    "sequential_impulse": [{"velocity_iterations": 4}, {"velocity_iterations": 16}, {"velocity_iterations": 32},
                           {"position_correction": "baumgarte"}, {"warm_starting": False}, {"block_solver": False}],
    "impulse": [{"iterations": 5}, {"iterations": 20}, {"projection": "nonlinear"}, {"projection": "none"}],
    "penalty": [{"contact_hertz": 50.0}],
    "hybrid": [{"iterations": 5}, {"projection": "none"}],
}


def _generic_sweep(decl):
    out = []
    for k, s in decl.items():
        if isinstance(s.default, bool):
            continue
        if isinstance(s.default, int) and any(w in k for w in ("iter", "substep")):
            for v in (max(s.lo or 1, s.default // 2), min(s.hi or 1e9, s.default * 2)):
                if v != s.default:
                    out.append({k: int(v)})
        elif isinstance(s.default, str):
            out += [{k: c} for c in s.choices if c != s.default]
    return out[:5]


def configs_for(mode, quick=False):
    from physics import solvers
    decl = solvers.get(mode).settings
    cfgs = [Config(mode, {}, mode, default=True)]
    if quick:
        return cfgs
    for var in SWEEPS.get(mode) or _generic_sweep(decl):
        var = {k: v for k, v in var.items() if k in decl}
        if not var:
            continue
        label = mode + " " + " ".join(f"{k}={v}" for k, v in var.items())
        cfgs.append(Config(mode, var, label))
    return cfgs


def available_modes():
    import physics
    return physics.solvers_available()


# -- timing ------------------------------------------------------------------------------------
def _scene_metrics(sim, top, p0, width=None):
    com = sim.state()[0]
    m = {"top_drift": float(np.hypot(*(com[top] - p0[top]))) if top is not None else None}
    mx, mean = refs.penetration(sim)
    m["max_penetration"], m["mean_penetration"] = mx, mean
    d = sim.dynamic
    m["escaped"] = int(np.sum(com[d, 1] < -2.0)) if width is None else \
        int(np.sum((com[d, 1] < -2.0) | (np.abs(com[d, 0]) > 0.5 * width + 2.0)))
    m["finite"] = bool(np.all(np.isfinite(com)))
    return m


def _top_index(sim):
    com = sim.state()[0]
    dyn = np.nonzero(sim.dynamic)[0]
    return int(dyn[np.argmax(com[dyn, 1])]) if len(dyn) else None


def interleaved(sims, steps, chunk, warm, budget_s=None):
    """Step every sim ``steps`` times, chunk by chunk in turn.  Returns (first-step seconds per sim,
    per-chunk seconds/step per sim for the chunks after ``warm`` steps, steps done, error)."""
    first, chunks = {}, {k: [] for k in sims}
    err = None
    t_start = time.perf_counter()
    for k, s in sims.items():
        t = time.perf_counter()
        try:
            s.step()
        except Exception as exc:
            return first, chunks, 0, f"{k}: {type(exc).__name__}: {exc}"
        first[k] = time.perf_counter() - t
    done = 1
    gc_was = gc.isenabled()
    gc.disable()
    try:
        while done < steps:
            c = min(chunk, steps - done)
            for k, s in sims.items():
                t = time.perf_counter()
                try:
                    for _ in range(c):
                        s.step()
                except Exception as exc:
                    err = f"{k}: {type(exc).__name__}: {str(exc)[:200]}"
                    break
                el = (time.perf_counter() - t) / c
                if done >= warm:
                    chunks[k].append(el)
            if err:
                break
            done += c
            if budget_s and time.perf_counter() - t_start > budget_s and done < steps:
                err = f"stopped after {done} steps: over the {budget_s:.0f} s budget"
                break
    finally:
        if gc_was:
            gc.enable()
    return first, chunks, done, err


def _ratio(a, b):
    n = min(len(a), len(b))
    if n == 0:
        return None
    return float(np.median(np.array(a[:n]) / np.array(b[:n])))


def speed_scene(key, configs, plan, with_refs=True, budget_s=None, progress=None):
    """Rows for every configuration (and the references) on one scene."""
    desc, src = scene_desc(key)
    if desc is None:
        return [], None
    width = None
    if key.startswith("rain"):
        xs = [b["position"][0] for b in desc["bodies"] if b.get("kind") == "static"]
        width = max(xs) - min(xs) if xs else None
    rows, ref_chunks, ref_metrics, ref_first = [], {e: [] for e in REF_ENGINES}, {}, {}
    for cfg in configs:
        if progress:
            progress.set_description(f"{key}: {cfg.label}"[:60])
        sims = {}
        try:
            sims["ours"] = make_ours(key, desc, src, cfg.mode, cfg.settings)
        except Exception as exc:
            rows.append(dict(scene=key, engine="stelkropp", mode=cfg.mode, label=cfg.label, settings=cfg.settings,
                             default=cfg.default, status=f"build failed: {exc}"))
            continue
        if with_refs:
            for e in REF_ENGINES:
                sims[e] = refs.build(e, desc)
        top = _top_index(sims["ours"])
        p0 = {k: s.state()[0].copy() for k, s in sims.items()}
        first, chunks, done, err = interleaved(sims, plan["steps"], plan["chunk"], plan["warm"], budget_s)
        ours = chunks["ours"]
        row = dict(scene=key, engine="stelkropp", mode=cfg.mode, label=cfg.label, settings=cfg.settings,
                   default=cfg.default, source=src, steps=done, sim_time=done * sims["ours"].dt,
                   ms_step=float(np.median(ours)) * 1e3 if ours else None,
                   ms_step_min=float(np.min(ours)) * 1e3 if ours else None,
                   chunks=len(ours), first_step_s=first.get("ours"), status=err or "ok")
        for e in REF_ENGINES:
            if e in sims and not (err and err.startswith(e)):
                row[f"ratio_{e}"] = _ratio(ours, chunks[e])
                ref_chunks[e] += chunks[e]
                ref_first.setdefault(e, first.get(e))
        try:
            row.update(_scene_metrics(sims["ours"], top, p0["ours"], width))
        except Exception as exc:
            row["status"] = f"{row['status']}; metrics failed: {exc}"
        if not row.get("finite", True):
            row["status"] = "non-finite state"
        row["error"] = row.get(SCENES[key]["error"])
        rows.append(row)
        if with_refs and not ref_metrics and done == plan["steps"]:
            for e in REF_ENGINES:
                ref_metrics[e] = _scene_metrics(sims[e], top, p0[e], width)
        if progress:
            progress.update(1)
        del sims
        gc.collect()
    if with_refs:
        it = {"pymunk": f"iterations {refs.PYMUNK_ITERATIONS}",
              "pybox2d": f"Step(dt, {refs.BOX2D_VELOCITY_ITERATIONS}, {refs.BOX2D_POSITION_ITERATIONS})"}
        for e in REF_ENGINES:
            c = ref_chunks[e]
            row = dict(scene=key, engine=e, mode=e, label=f"{e} ({it[e]})", settings={}, default=True, source=src,
                       steps=plan["steps"], sim_time=plan["steps"] * desc["world"]["dt"],
                       ms_step=float(np.median(c)) * 1e3 if c else None,
                       ms_step_min=float(np.min(c)) * 1e3 if c else None, chunks=len(c),
                       first_step_s=ref_first.get(e), status="ok", **ref_metrics.get(e, {}))
            row["error"] = row.get(SCENES[key]["error"])
            rows.append(row)
    return rows, src


# -- scaling -----------------------------------------------------------------------------------------
def scaling(ns, mode=DEFAULT_MODE, with_refs=True, progress=None):
    rows = []
    for n in ns:
        if progress:
            progress.set_description(f"scaling: {n} bodies")
        desc = refs.with_world(refs.columns(n), **BENCH_WORLD)
        sims = {"ours": refs.OursSim(desc, solver=mode)}
        if with_refs:
            for e in REF_ENGINES:
                sims[e] = refs.build(e, desc)
        chunk = int(min(30, max(3, 3000 // n)))
        first, chunks, done, err = interleaved(sims, 1 + chunk * 8, chunk, 1 + 2 * chunk)
        for k, c in chunks.items():
            eng = "stelkropp" if k == "ours" else k
            r = dict(n=n, engine=eng, mode=mode if k == "ours" else k,
                     ms_step=float(np.median(c)) * 1e3 if c else None, chunks=len(c), status=err or "ok",
                     contacts=int(sims["ours"].world._contacts.n) if k == "ours" else None)
            if k == "ours":
                for e in REF_ENGINES:
                    if e in chunks:
                        r[f"ratio_{e}"] = _ratio(c, chunks[e])
            rows.append(r)
        if progress:
            progress.update(1)
        del sims
        gc.collect()
    return rows


def loglog_slope(rows, engine):
    pts = [(r["n"], r["ms_step"]) for r in rows if r["engine"] == engine and r.get("ms_step")]
    if len(pts) < 2:
        return None
    x, y = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
    return float(np.polyfit(x, y, 1)[0])


# -- overhead and compile ----------------------------------------------------------------------------
def overhead(modes, reps=20000):
    import physics
    out = {}

    def per_step(world, k):
        world.step()
        t = time.perf_counter()
        for _ in range(k):
            world.step()
        return 1e6 * (time.perf_counter() - t) / k

    from .profile import call_overhead
    out["kernel_call"] = call_overhead(reps=reps // 4)
    w = physics.World(sleeping=False)
    out["empty_world_us"] = min(per_step(w, reps) for _ in range(3))
    out["one_body_us"], out["box_on_ground_us"] = {}, {}
    for m in modes:
        w = physics.World(solver=m, sleeping=False, gravity=(0, 0))
        w.add_body(physics.Polygon.box(1, 1), position=(0, 0))
        out["one_body_us"][m] = min(per_step(w, reps // 10) for _ in range(3))
        w = physics.World(solver=m, sleeping=False, gravity=(0, -10))
        w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
        w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5))
        out["box_on_ground_us"][m] = min(per_step(w, reps // 10) for _ in range(3))
    return out


_COMPILE_SCRIPT = r"""
import json, sys, time
t0 = time.perf_counter()
import physics
t_import = time.perf_counter() - t0
out = {"import_s": t_import, "first_step_s": {}}
modes = sys.argv[1].split(",")
for m in modes:
    w = physics.World(solver=m, sleeping=True, gravity=(0, -10))
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    a = w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5))
    w.add_body(physics.Circle(0.3), position=(0.2, 1.4))
    w.add_body(physics.Polygon.regular(6, 0.4), position=(-0.3, 2.3))
    w.add_spring(a, None, anchor_b=(0, 3), stiffness=50, damping=1)
    t = time.perf_counter()
    for _ in range(3):
        w.step()
    out["first_step_s"][m] = time.perf_counter() - t
out["startup_s"] = time.perf_counter() - t0
print("@@" + json.dumps(out))
"""


def source_hash():
    from physics._jit import _source_hash
    return _source_hash()


def compile_times(modes, phases=("cold", "cached"), timeout=1500):
    """Kernel compile on first use and a cached start, each timed in a new process: import time,
    the first three steps per mode (a scene with polygons, a circle and a spring; the first mode
    also compiles the shared stages), and the total from start to the last step.

    ``cold`` runs with a fresh, empty numba cache (a temporary directory); ``cached`` with the
    core's own cache directory, so run it after the kernels have been used once."""
    out = {}
    for phase in phases:
        with tempfile.TemporaryDirectory(prefix="stelkropp-bench-cache-") as tmp:
            env = dict(os.environ)
            if phase == "cold":
                env["STELKROPP_CACHE_DIR"] = tmp
                env.pop("NUMBA_CACHE_DIR", None)
            t = time.perf_counter()
            try:
                p = subprocess.run([sys.executable, "-c", _COMPILE_SCRIPT, ",".join(modes)], env=env,
                                   capture_output=True, text=True, timeout=timeout, cwd=str(refs.ROOT))
                line = [ln for ln in p.stdout.splitlines() if ln.startswith("@@")]
                out[phase] = json.loads(line[-1][2:]) if line else {"error": p.stderr[-500:]}
            except subprocess.TimeoutExpired:
                out[phase] = {"error": f"timeout after {timeout} s"}
            out[phase]["process_s"] = time.perf_counter() - t
            out[phase]["source_hash"] = source_hash()
    return out


# -- accuracy ----------------------------------------------------------------------------------------
def accuracy_runs(modes, quick=False, with_refs=True, progress=None):
    rows = []
    scen = list(accuracy.SCENARIOS)
    dts = (1 / 60,) if quick else (1 / 30, 1 / 60, 1 / 120)

    def record(engine, mode, label, settings, dt, integrator, name, metrics, is_default):
        for m in metrics:
            rows.append(dict(engine=engine, mode=mode, label=label, settings=settings, dt=dt, integrator=integrator,
                             scenario=name, default=is_default, **m))

    jobs = []
    if with_refs:
        for e in REF_ENGINES:
            for dt in dts:
                jobs.append((e, None, dt, None))
    for mode in modes:
        from physics import solvers
        uses_int = getattr(solvers.get(mode), "uses_integrator", False)
        for cfg in configs_for(mode, quick):
            jobs.append(("stelkropp", cfg, 1 / 60, None))
            if cfg.default and not quick:
                for dt in dts:
                    if dt != 1 / 60:
                        jobs.append(("stelkropp", cfg, dt, None))
                if uses_int:
                    for integ in ("euler", "rk4"):
                        jobs.append(("stelkropp", cfg, 1 / 60, integ))
    if progress:
        progress.total += len(jobs)
        progress.refresh()
    for engine, cfg, dt, integ in jobs:
        names = scen if dt == 1 / 60 and integ is None else list(accuracy.DT_SCENARIOS)
        if engine == "stelkropp":
            label = cfg.label + (f" integrator={integ}" if integ else "")
            if progress:
                progress.set_description(f"accuracy: {label} dt=1/{round(1 / dt)}"[:60])

            def make(d, cfg=cfg, integ=integ):
                return refs.OursSim(d, solver=cfg.mode, settings=cfg.settings, integrator=integ)
            for name in names:
                record("stelkropp", cfg.mode, label, cfg.settings, dt, integ or "symplectic_euler", name,
                       accuracy.run_scenario(name, make, dt), cfg.default and integ is None)
        else:
            if progress:
                progress.set_description(f"accuracy: {engine} dt=1/{round(1 / dt)}")
            for name in names:
                record(engine, engine, engine, {}, dt, None, name,
                       accuracy.run_scenario(name, lambda d, e=engine: refs.build(e, d), dt), True)
        if progress:
            progress.update(1)
    return rows


# -- output -------------------------------------------------------------------------------------------
def _fmt(v, nd=3):
    if v is None:
        return "-"
    if isinstance(v, float):
        if v != 0 and (abs(v) < 10 ** -nd or abs(v) >= 1e5):
            return f"{v:.2e}"
        return f"{v:.{nd}f}"
    return str(v)


def speed_table(rows, defaults_only=False):
    hdr = ["scene", "configuration", "ms/step", "x pymunk", "x pybox2d", "error", "first step s", "status"]
    out = []
    for r in rows:
        if defaults_only and not r.get("default"):
            continue
        out.append([r["scene"], r["label"], _fmt(r.get("ms_step")), _fmt(r.get("ratio_pymunk"), 2),
                    _fmt(r.get("ratio_pybox2d"), 2), _fmt(r.get("error"), 4), _fmt(r.get("first_step_s"), 2),
                    r.get("status", "")[:40]])
    return hdr, out


def text_table(hdr, rows):
    w = [max(len(str(x)) for x in col) for col in zip(hdr, *rows)] if rows else [len(h) for h in hdr]
    line = "  ".join(h.ljust(n) for h, n in zip(hdr, w))
    body = ["  ".join(str(x).ljust(n) for x, n in zip(r, w)) for r in rows]
    return "\n".join([line, "-" * len(line), *body])


def md_table(hdr, rows):
    return "\n".join(["| " + " | ".join(hdr) + " |", "|" + "---|" * len(hdr),
                      *["| " + " | ".join(str(x).replace("|", "/") for x in r) + " |" for r in rows]])


def _csv(path, rows, keys=None):
    if not rows:
        return
    keys = keys or sorted({k for r in rows for k in r})
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: json.dumps(v) if isinstance(v, (dict, list)) else v for k, v in r.items()})


def write_outputs(res, outdir):
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    with open(outdir / "bench.json", "w") as f:
        json.dump(res, f, indent=1, default=float)
    _csv(outdir / "speed.csv", res.get("speed", []),
         ["scene", "engine", "mode", "label", "settings", "default", "ms_step", "ms_step_min", "ratio_pymunk",
          "ratio_pybox2d", "error", "top_drift", "max_penetration", "mean_penetration", "escaped", "steps",
          "sim_time", "chunks", "first_step_s", "status", "source"])
    _csv(outdir / "scaling.csv", res.get("scaling", []),
         ["n", "engine", "mode", "ms_step", "ratio_pymunk", "ratio_pybox2d", "contacts", "chunks", "status"])
    _csv(outdir / "accuracy.csv", res.get("accuracy", []),
         ["engine", "mode", "label", "settings", "dt", "integrator", "scenario", "metric", "value", "expected",
          "error", "unit", "default", "note"])
    prof = []
    for scene, p in (res.get("profile") or {}).items():
        for stage, us in p["us_per_step"].items():
            prof.append(dict(scene=scene, stage=stage, us_per_step=us,
                             share=us / p["us_per_step"]["total"] if p["us_per_step"]["total"] else None))
    _csv(outdir / "profile.csv", prof, ["scene", "stage", "us_per_step", "share"])
    from . import plots
    return plots.make_all(res, outdir)


def _git_commit():
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=refs.ROOT, capture_output=True,
                              text=True, timeout=10).stdout.strip()
    except Exception:
        return ""


def meta(quick):
    import numba
    import pymunk
    import Box2D
    return dict(date=datetime.datetime.now().isoformat(timespec="seconds"), quick=quick, commit=_git_commit(),
                python=platform.python_version(), numpy=np.__version__, numba=numba.__version__,
                pymunk=pymunk.version, pybox2d=getattr(Box2D, "__version__", "2.3"), machine=platform.machine(),
                cpus=os.cpu_count(), platform=platform.platform())


def substep_fit(speed, scene, mode=DEFAULT_MODE):
    """(ms per sub-step, ms fixed per step) from the sub-step sweep of ``mode`` on ``scene``: a line
    through ms/step against sub-steps (the defaults and the configurations that change only them)."""
    from physics import solvers
    try:
        dflt = solvers.get(mode).settings["substeps"].default
    except (KeyError, ValueError, ImportError):
        return None
    # noise-cancelled times: each configuration's interleaved ratio to pymunk times pymunk's pooled median
    pm = next((r.get("ms_step") for r in speed if r["scene"] == scene and r["engine"] == "pymunk"), None)

    def ms(r):
        return r["ratio_pymunk"] * pm if pm and r.get("ratio_pymunk") else r["ms_step"]
    pts = [((r["settings"] or {}).get("substeps", dflt), ms(r)) for r in speed
           if r["scene"] == scene and r["engine"] == "stelkropp" and r["mode"] == mode and r.get("ms_step")
           and set(r["settings"] or {}) <= {"substeps"} and r.get("status") == "ok"]
    if len({p[0] for p in pts}) < 3:
        return None
    x, y = np.array(pts, float).T
    a, b = np.polyfit(x, y, 1)
    return float(a), float(b), int(dflt)


def summary_lines(res):
    """Human-readable lines on the targets (used by the terminal and the docs)."""
    L = []
    sp = res.get("speed", [])
    for key in ("pyramid20", "pyramid40", "rain1000"):
        r = next((x for x in sp if x["scene"] == key and x["engine"] == "stelkropp" and x.get("default")
                  and x["mode"] == DEFAULT_MODE), None)
        pm = next((x for x in sp if x["scene"] == key and x["engine"] == "pymunk"), None)
        if not r or r.get("ms_step") is None:
            continue
        rp = r.get("ratio_pymunk")
        txt = (f"{key}: {DEFAULT_MODE} {r['ms_step']:.3f} ms/step = {_fmt(rp, 2)}x pymunk"
               f" ({_fmt(pm and pm.get('ms_step'))} ms), {_fmt(r.get('ratio_pybox2d'), 2)}x pybox2d")
        if rp is not None and key in ("pyramid20", "rain1000"):
            txt += " -- target (<= pymunk) " + ("MET" if rp <= 1.0 else "NOT MET")
        if key in BOX2D_V3 and pm and pm.get("ms_step"):
            (lo, hi), pm_ref = BOX2D_V3[key]
            est = pm["ms_step"] * 0.5 * (lo + hi) / pm_ref
            ours_ms = rp * pm["ms_step"] if rp is not None else r["ms_step"]  # noise-cancelled
            txt += f"; vs Box2D v3 (estimated {est:.3f} ms here, from pymunk's time): {ours_ms / est:.1f}x"
        L.append(txt)
    for key in ("pyramid20", "pyramid40", "rain1000"):
        f = substep_fit(sp, key)
        if f and f[1] <= 0:
            L.append(f"{key}: {DEFAULT_MODE} costs {f[0]:.3f} ms per sub-step (the fixed part is within the noise)")
        elif f:
            a, b, d = f
            L.append(f"{key}: {DEFAULT_MODE} costs {a:.3f} ms per sub-step + {b:.3f} ms per step "
                     f"(collision, contact preparation, restitution, overhead); at the default {d} sub-steps "
                     f"the sub-steps are {100 * a * d / (a * d + b):.0f}% of the step")
    sc = res.get("scaling", [])
    if sc:
        for e in ("stelkropp", *REF_ENGINES):
            s = loglog_slope(sc, e)
            if s is not None:
                L.append(f"scaling {e}: ms/step ~ n^{s:.2f} from {sc[0]['n']} to {sc[-1]['n']} bodies")
    ov = res.get("overhead")
    if ov:
        e = ov["empty_world_us"]
        L.append(f"world.step() overhead, empty world: {e:.2f} us (target < 20 us: {'MET' if e < 20 else 'NOT MET'}); "
                 f"1 body ({DEFAULT_MODE}): {_fmt(ov['one_body_us'].get(DEFAULT_MODE), 1)} us; "
                 f"box on ground: {_fmt(ov['box_on_ground_us'].get(DEFAULT_MODE), 1)} us")
        kc = ov.get("kernel_call")
        if kc:
            L.append("kernel call from Python: " + ", ".join(
                f"{k} ({v['arrays']} arrays) {v['us_per_call']:.2f} us" for k, v in kc.items()))
    ct = res.get("compile")
    if ct:
        for ph in ("cold", "cached"):
            c = ct.get(ph, {})
            if "startup_s" in c:
                fs = ", ".join(f"{m} {v:.2f} s" for m, v in c["first_step_s"].items())
                L.append(f"{ph} start: import {c['import_s']:.2f} s, first steps: {fs}; total {c['startup_s']:.2f} s"
                         + (f" (target < 3 s: {'MET' if c['startup_s'] < 3 else 'NOT MET'})" if ph == "cached" else ""))
            elif c:
                L.append(f"{ph} start: {c.get('error', '?')}")
    return L


def print_report(res, file=sys.stdout):
    hdr, rows = speed_table(res.get("speed", []))
    print("\nSpeed (median ms/step; x ref = ours / ref per chunk, interleaved; error per scene: "
          "pyramids top-box drift m, rain max penetration m)", file=file)
    print(text_table(hdr, rows), file=file)
    if res.get("scaling"):
        print("\nScaling (columns of 10 boxes)", file=file)
        sh = ["n", "engine", "ms/step", "x pymunk", "x pybox2d"]
        print(text_table(sh, [[r["n"], r["engine"], _fmt(r["ms_step"]), _fmt(r.get("ratio_pymunk"), 2),
                               _fmt(r.get("ratio_pybox2d"), 2)] for r in res["scaling"]]), file=file)
    if res.get("accuracy"):
        print("\nAccuracy (defaults, dt 1/60; error: relative or absolute as per metric, ideal 0)", file=file)
        ah, ar = accuracy_table(res["accuracy"])
        print(text_table(ah, ar), file=file)
    if res.get("profile"):
        from .profile import format_profile
        print("", file=file)
        for k, p in res["profile"].items():
            print(format_profile(k, p), file=file)
    print("", file=file)
    for ln in summary_lines(res):
        print(ln, file=file)


def accuracy_table(acc):
    """Metric rows x engines/modes (defaults, dt 1/60): value (error)."""
    cols = []
    for r in acc:
        if r.get("default") and abs(r["dt"] - 1 / 60) < 1e-12 and r["label"] not in cols:
            cols.append(r["label"])
    metrics = []
    for r in acc:
        if r["metric"] not in metrics and r["metric"] not in accuracy.SCENARIOS:
            metrics.append(r["metric"])
    exp = {}
    table = {}
    for r in acc:
        if r.get("default") and abs(r["dt"] - 1 / 60) < 1e-12:
            table[(r["metric"], r["label"])] = r
            exp.setdefault(r["metric"], r.get("expected"))
    rows = []
    for m in metrics:
        e = exp.get(m)
        row = [m, _fmt(e, 3) if not isinstance(e, list) else str(e)]
        for c in cols:
            r = table.get((m, c))
            if r is None:
                failed = [x for x in acc if x["label"] == c and x.get("default") and abs(x["dt"] - 1 / 60) < 1e-12
                          and x["metric"] in accuracy.SCENARIOS and m.startswith(x["metric"].split("_")[0])]
                row.append("failed" if failed else "-")
                continue
            v = r.get("value")
            if v is None and "not at rest" in r.get("note", ""):
                row.append("> " + r["note"].split("after ")[-1])
                continue
            v = "/".join(_fmt(x, 3) for x in v) if isinstance(v, list) else _fmt(v, 4)
            row.append(v if r.get("note", "").startswith("failed") is False else "failed")
        rows.append(row)
    return ["metric", "expected", *cols], rows


# -- docs ----------------------------------------------------------------------------------------------
def write_docs(res, outdir=RESULTS, path=DOCS):
    path.parent.mkdir(parents=True, exist_ok=True)
    rel = os.path.relpath(outdir, path.parent)
    path.write_text(render_docs(res, rel, outdir))
    return path


DOCS_NOTES = (Path(__file__).resolve().parent / "results" / "notes.md")


def render_docs(res, rel, outdir):
    m = res["meta"]
    L = ["# Benchmarks", "",
         "<!-- generated by `python -m bench --write-docs` (or `--docs-only` from bench/results/bench.json); "
         "edit bench/run.py or bench/results/notes.md, not this file -->", "",
         f"Latest run: {m['date']}, commit `{m.get('commit', '')}`, {m.get('cpus')} CPUs ({m.get('platform', '')}), "
         f"Python {m['python']}, numba {m['numba']}, pymunk {m['pymunk']}, pybox2d {m['pybox2d']}"
         f"{' -- QUICK run' if m.get('quick') else ''}; wall time {m.get('wall_s', 0):.0f} s.", "",
         "## Regenerate", "",
         "```bash",
         ".venv/bin/python -m bench                # full suite (< 20 min on 2 cores): bench/results/*.json|csv|png",
         ".venv/bin/python -m bench --write-docs   # the same, then rewrites this page",
         ".venv/bin/python -m bench --quick        # CI smoke (< 2 min), results in bench/results/quick/",
         ".venv/bin/python -m bench --docs-only    # re-plot and rewrite this page from bench/results/bench.json",
         ".venv/bin/python -m bench.profile --scene pyramid20   # stage breakdown of one scene",
         "```", "",
         "Options: `--modes soft_step,sequential_impulse`, `--scenes pyramid20,rain1000`, "
         "`--parts speed,accuracy,...`, `--no-refs`, `--no-compile`, `--budget SECONDS`.", "",
         "## How it is measured", "",
         "* Scenes are built from one description (the shipped scene file when there is one, else generated in "
         "`bench/refs.py`) in Stelkropp, pymunk 7 (Chipmunk2D) and pybox2d 2.3.10 (Box2D 2.3): same bodies, "
         "vertices, masses (density x area), friction, gravity (-10), dt (1/60), sleeping off. Friction is "
         "combined as the geometric mean in every engine (pymunk shapes get sqrt(mu), since Chipmunk multiplies). "
         "pymunk runs 10 iterations (its default; other Chipmunk defaults kept, e.g. `collision_slop` 0.1 m), "
         "pybox2d `Step(dt, 8, 3)`.",
         "* Speed: each configuration runs its scene in chunks, interleaved chunk by chunk with pymunk and pybox2d "
         "(ours, pymunk, pybox2d, ours, ...) on fresh copies of the same scene; warm-up chunks are not timed. "
         "ms/step is the median over timed chunks; `x pymunk` is the median of the per-chunk ratios ours/pymunk "
         "(below 1: faster than pymunk). The first step (numba compile or cache load) is reported separately as "
         "`first step s` and never enters ms/step. The reference rows pool the references' chunks over all "
         "configurations of the scene.",
         "* Error per scene: pyramids -- how far the top box moved over the run (ideal 0); rain -- the maximum "
         "penetration at the end. Penetration is measured from the final poses by exact polygon geometry (SAT), "
         "the same code for every engine, so engine-internal slop and skin radii count the same way.",
         ""]
    L += ["## Summary", ""] + [f"* {ln}" for ln in summary_lines(res)] + [""]
    sp = res.get("speed", [])
    if sp:
        L += ["## Speed: every scene, mode and setting", "",
              "Columns: median ms/step; ours/pymunk and ours/pybox2d (same run, interleaved; below 1 is faster); "
              "the scene's error (pyramids: top-box drift in m, rain: max penetration in m); the first step "
              "(compile or cache load) in seconds.", ""]
        for key in dict.fromkeys(r["scene"] for r in sp):
            sc = res["scenes"].get(key, {})
            hdr, rows = speed_table([r for r in sp if r["scene"] == key])
            L += [f"### {sc.get('title', key)}", "",
                  f"Source: {sc.get('source')}; {sc.get('steps')} steps ({sc.get('steps', 0) / 60:.1f} s simulated), "
                  f"chunks of {sc.get('chunk')}, first {sc.get('warm')} steps untimed.", "",
                  md_table(hdr, rows), "",
                  f"![{key}: ms/step vs error]({rel}/pareto_{key}.png)", ""]
    if res.get("scaling"):
        sc = res["scaling"]
        L += ["## Scaling with body count", "",
              "Free-standing columns of 10 boxes on one ground (contacts per body constant), default mode. "
              "Log-log slopes: " + ", ".join(f"{e} {loglog_slope(sc, e):.2f}" for e in ("stelkropp", *REF_ENGINES)
                                             if loglog_slope(sc, e) is not None) + " (1.0 is linear).", "",
              md_table(["bodies", "engine", "ms/step", "x pymunk", "x pybox2d"],
                       [[r["n"], r["engine"], _fmt(r["ms_step"]), _fmt(r.get("ratio_pymunk"), 2),
                         _fmt(r.get("ratio_pybox2d"), 2)] for r in sc]), "",
              f"![scaling]({rel}/scaling.png)", ""]
    if res.get("accuracy"):
        ah, ar = accuracy_table(res["accuracy"])
        L += ["## Accuracy against known answers", "",
              "Scenarios (`bench/accuracy.py`; dt 1/60 and gravity -10 unless the sweep changes dt), the same "
              "in every engine:", "",
              accuracy.__doc__[accuracy.__doc__.index("* ``spring``"):].rstrip(), "",
              "Values with default settings at dt 1/60 (velocities of the elastic collision as a/b; "
              "the full sweep over settings, dt and integrators is in `bench/results/accuracy.csv`):", "",
              md_table(ah, ar), "",
              f"![accuracy]({rel}/accuracy.png)", ""]
        L += _accuracy_sweep_md(res["accuracy"])
    if res.get("profile"):
        from .profile import STAGES, narrowphase_per_pair
        st = [*STAGES, "python/other", "total"]
        rows = []
        for k, p in res["profile"].items():
            us = p["us_per_step"]
            rows.append([k, p["bodies"], p["pairs"], p["contacts"],
                         *[f"{us[s]:.0f} ({100 * us[s] / us['total']:.0f}%)" if s != "total" else f"{us[s]:.0f}"
                           for s in st], f"{narrowphase_per_pair(p):.0f}"])
        L += ["## Where the default mode's step goes", "",
              f"`{DEFAULT_MODE}` with default settings, sleeping off; microseconds per step in each pipeline stage "
              "(timers wrapped around the stage entry points while `world.step()` runs; `python/other` is the "
              "step's time outside every stage). Regenerate one scene with "
              "`python -m bench.profile --scene pyramid20`.", "",
              md_table(["scene", "bodies", "pairs", "manifolds", *st, "narrow ns/pair"], rows), "",
              f"![profile]({rel}/profile.png)", ""]
    ov, ct = res.get("overhead"), res.get("compile")
    if ov or ct:
        L += ["## Overhead and compile time", ""]
        if ov:
            L += [f"* `world.step()` on an empty world: {ov['empty_world_us']:.2f} us.",
                  "* One free body / a box resting on the ground, per mode (us per step): " + "; ".join(
                      f"{md}: {ov['one_body_us'][md]:.1f} / {ov['box_on_ground_us'][md]:.1f}"
                      for md in ov["one_body_us"]) + "."]
        if ct:
            for ph in ("cold", "cached"):
                c = ct.get(ph, {})
                if "startup_s" in c:
                    L.append(f"* {ph} start (new process, {'empty' if ph == 'cold' else 'warm'} numba cache): "
                             f"import {c['import_s']:.2f} s, first three steps of a small scene per mode: "
                             + ", ".join(f"{md} {v:.2f} s" for md, v in c["first_step_s"].items())
                             + f"; total {c['startup_s']:.2f} s.")
        L.append("")
    if DOCS_NOTES.exists():
        L += [DOCS_NOTES.read_text().rstrip(), ""]
    L += ["## Files", "", "`bench/results/`: `bench.json` (everything), `speed.csv`, `scaling.csv`, `accuracy.csv`, "
          "`profile.csv`, and the PNGs above.", ""]
    return "\n".join(L)


def _accuracy_sweep_md(acc):
    """Per metric, the best and worst configuration of ours, and the dt / integrator sweeps."""
    L = ["### Settings, time step and integrator", "",
         "Best and worst error of each metric over every mode, setting, dt and integrator tried "
         "(full list in `accuracy.csv`):", ""]
    rows = []
    for m in dict.fromkeys(r["metric"] for r in acc):
        rs = [r for r in acc if r["metric"] == m and r["engine"] == "stelkropp" and r.get("error") is not None]
        if not rs:
            continue
        best = min(rs, key=lambda r: r["error"])
        worst = max(rs, key=lambda r: r["error"])

        def name(r):
            return f"{r['label']} dt=1/{round(1 / r['dt'])}"
        rows.append([m, _fmt(best["error"], 4), name(best), _fmt(worst["error"], 4), name(worst)])
    L += [md_table(["metric", "best error", "configuration", "worst error", "configuration"], rows), ""]
    return L


# -- main -----------------------------------------------------------------------------------------------
def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m bench", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="CI smoke: default settings only, short runs (< 2 min)")
    ap.add_argument("--out", type=Path, default=None,
                    help="results directory (default bench/results, or bench/results/quick with --quick)")
    ap.add_argument("--modes", default=None, help="comma-separated solver modes (default: every available mode)")
    ap.add_argument("--scenes", default=None, help=f"comma-separated scenes from {list(SCENES)}")
    ap.add_argument("--parts", default="overhead,compile,speed,scaling,accuracy,profile",
                    help="comma-separated parts to run (default: all)")
    ap.add_argument("--no-refs", action="store_true", help="skip pymunk and pybox2d")
    ap.add_argument("--no-compile", action="store_true", help="skip the cold/cached compile subprocesses")
    ap.add_argument("--budget", type=float, default=None, help="seconds per configuration and scene before it is cut")
    ap.add_argument("--write-docs", action="store_true", help="rewrite docs/benchmarks.md from this run")
    ap.add_argument("--docs-only", action="store_true", help="re-plot and rewrite the docs from the saved results")
    ap.add_argument("--tiny", action="store_true", help=argparse.SUPPRESS)  # tests: even smaller than --quick
    a = ap.parse_args(argv)
    outdir = a.out or (RESULTS / "quick" if (a.quick or a.tiny) else RESULTS)

    if a.docs_only:
        res = json.loads((outdir / "bench.json").read_text())
        write_outputs(res, outdir)
        print(f"wrote {write_docs(res, outdir)}")
        return 0

    from tqdm import tqdm
    quick = a.quick or a.tiny
    modes = a.modes.split(",") if a.modes else available_modes()
    if quick and not a.modes:  # the smoke run: the default mode and the classic solver
        modes = [m for m in modes if m in QUICK_MODES] or modes[:1]
    parts = set(a.parts.split(","))
    if quick or a.no_compile:
        parts.discard("compile")
    scenes = a.scenes.split(",") if a.scenes else [k for k, s in SCENES.items() if not quick or s["quick"]]
    if a.tiny:
        scenes = scenes if a.scenes else ["pyramid20"]
    budget = a.budget or 20.0
    res = {"meta": meta(quick), "modes": modes, "scenes": {}}
    res["meta"]["source_hash"] = source_hash()
    t_all = time.perf_counter()
    configs = {m: configs_for(m, quick) for m in modes}
    units = 0
    if "speed" in parts:
        units += sum(len(configs[m]) if SCENES[s]["sweep"] else 1 for s in scenes for m in modes)
    scale_ns = [100, 1000] if quick else [100, 300, 1000, 3000, 10000]
    if a.tiny:
        scale_ns = [100, 300]
    units += len(scale_ns) if "scaling" in parts else 0
    bar = tqdm(total=units, unit="run", dynamic_ncols=True, file=sys.stderr)
    try:
        if "compile" in parts:
            # cold: the default mode only (every other mode's first use shows as its first step below)
            bar.set_description("compile: cold start of the default mode (subprocess)")
            res["compile"] = compile_times([DEFAULT_MODE if DEFAULT_MODE in modes else modes[0]], ("cold",))
        if "overhead" in parts:
            bar.set_description("overhead per step")
            res["overhead"] = overhead(modes, reps=4000 if quick else 20000)
        if "speed" in parts:
            res["speed"] = []
            for s in scenes:
                plan = dict(SCENES[s]["quick"] if quick else SCENES[s]["full"])
                if a.tiny:
                    plan = dict(steps=40, chunk=10, warm=10)
                cf = [c for m in modes for c in (configs[m] if SCENES[s]["sweep"] else configs[m][:1])]
                rows, src = speed_scene(s, cf, plan, not a.no_refs, budget, bar)
                res["speed"] += rows
                res["scenes"][s] = dict(source=src, title=SCENES[s]["title"], error=SCENES[s]["error"], **plan)
        if "scaling" in parts:
            res["scaling"] = scaling(scale_ns, DEFAULT_MODE if DEFAULT_MODE in modes else modes[0],
                                     not a.no_refs, bar)
        if "accuracy" in parts:
            acc_modes = modes
            res["accuracy"] = accuracy_runs(acc_modes, quick, not a.no_refs, bar)
        if "profile" in parts:
            from .profile import stage_profile
            res["profile"] = {}
            for s in scenes:
                if SCENES[s].get("keep_world"):
                    continue
                bar.set_description(f"profile: {s}")
                desc, src = scene_desc(s)
                sim = make_ours(s, desc, src, DEFAULT_MODE, {})
                sim.step()
                # the rain is profiled once the pile has formed (as in its timed window)
                warm = 10 if quick else (SCENES[s]["full"]["warm"] * 4 if s.startswith("rain") else 60)
                res["profile"][s] = stage_profile(sim.world, steps=40 if quick else 300, warm=warm)
        if "compile" in parts:
            bar.set_description("compile: cached start (subprocess)")
            c = compile_times(modes, ("cached",))
            if c["cached"]["source_hash"] != res["meta"]["source_hash"] or c["cached"].get("startup_s", 99) > 10:
                # physics/ changed during the run (the cache is keyed on its sources): the first
                # process compiled afresh; a second one measures the cached start
                c = compile_times(modes, ("cached",))
                c["cached"]["note"] = "physics/ sources changed during the run; measured in a second process"
            res["compile"].update(c)
    finally:
        bar.close()
    res["meta"]["wall_s"] = time.perf_counter() - t_all
    pngs = write_outputs(res, outdir)
    print_report(res)
    print(f"\nresults: {outdir} ({', '.join(p.name for p in pngs)}); wall {res['meta']['wall_s']:.0f} s")
    if a.write_docs:
        print(f"wrote {write_docs(res, outdir)}")
    return 0
