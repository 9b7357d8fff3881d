"""Speed on the benchmark scenes: every configuration interleaved with the reference engines.

``speed_cases`` turns a scene and configurations into ``SpeedCase``s, ``run_speed_case`` runs one
(building every engine from the case's own description), ``speed_scene`` runs them in turn and
pools the references' chunks over all configurations of the scene into their own rows.
"""
from __future__ import annotations

import dataclasses
import gc

from .cases import Plan, SpeedCase
from .engines import build, engine_class
from .engines.ours import OursSim, loaded_world
from .metrics import scene_metrics, top_index
from .paths import ROOT
from .scenes import SCENES, container_width, scene_data
from .timing import chunk_ratio, interleaved, median_ms, min_ms


def make_ours(scene, config) -> OursSim:
    """Stelkropp for ``scene`` (a SceneData) in ``config``: the scene loader's world for a shipped
    file (so the benchmark runs what the sandbox loads), else built from the description."""
    world = loaded_world(scene.data, str(ROOT / scene.source)) if scene.from_file else None
    return OursSim(scene.desc, solver=config.mode, settings=config.settings, world=world,
                   integrator=config.integrator)


def speed_cases(key, configs, plan, engines=(), budget_s=None) -> list[SpeedCase]:
    """One case per configuration on scene ``key`` (no cases when the scene cannot be built)."""
    sd = scene_data(key)
    if sd is None:
        return []
    engines = scene_engines(key, engines)
    width = container_width(sd.desc) if key.startswith("rain") else None
    p = Plan(**plan)
    return [SpeedCase(sd, cfg, p, tuple(engines), budget_s, width) for cfg in configs]


def scene_engines(key, engines) -> tuple:
    """The engines of ``engines`` that model scene ``key`` (a joint scene: pymunk only)."""
    only = SCENES[key].engines
    return tuple(e for e in engines if only is None or e in only)


def _base_row(case):
    cfg = case.config
    return dict(scene=case.scene.key, engine="stelkropp", mode=cfg.mode, label=cfg.label, settings=cfg.settings,
                default=cfg.default)


def run_speed_case(case) -> dict:
    """Run one case.  Returns {"row": the configuration's row, "refs": {engine: {"chunks",
    "first", "metrics" (None unless asked for and the run completed)}}}."""
    try:
        ours = make_ours(case.scene, case.config)
    except Exception as exc:
        return {"row": dict(_base_row(case), status=f"build failed: {exc}"), "refs": {}}
    desc = case.scene.desc
    sims = {"ours": ours, **{e: build(e, desc) for e in case.engines}}
    top = top_index(ours)
    p0 = {k: s.state()[0].copy() for k, s in sims.items()}
    plan = case.plan
    first, chunks, done, err = interleaved(sims, plan.steps, plan.chunk, plan.warm, case.budget_s)
    c = chunks["ours"]
    row = dict(_base_row(case), source=case.scene.source, steps=done, sim_time=done * ours.dt,
               ms_step=median_ms(c), ms_step_min=min_ms(c), chunks=len(c), first_step_s=first.get("ours"),
               status=err or "ok")
    refs = {}
    for e in case.engines:
        if not (err and err.startswith(e)):
            row[f"ratio_{e}"] = chunk_ratio(c, chunks[e])
            refs[e] = {"chunks": chunks[e], "first": first.get(e), "metrics": None}
    try:
        row.update(scene_metrics(ours, top, p0["ours"], case.width))
    except Exception as exc:
        row["status"] = f"{row['status']}; metrics failed: {exc}"
    if not row.get("finite", True):
        row["status"] = "non-finite state"
    row["error"] = row.get(SCENES[case.scene.key].error)
    if case.ref_metrics and done == plan.steps:
        for e in case.engines:
            refs.setdefault(e, {"chunks": [], "first": None, "metrics": None})
            refs[e]["metrics"] = scene_metrics(sims[e], top, p0[e], case.width)
    return {"row": row, "refs": refs}


def reference_rows(key, plan, dt, source, engines, pooled) -> list[dict]:
    """One row per reference engine on scene ``key`` from its chunks pooled over every case."""
    rows = []
    for e in engines:
        p = pooled[e]
        c = p["chunks"]
        row = dict(scene=key, engine=e, mode=e, label=f"{e} ({engine_class(e).settings_label})", settings={},
                   default=True, source=source, steps=plan["steps"], sim_time=plan["steps"] * dt,
                   ms_step=median_ms(c), ms_step_min=min_ms(c), chunks=len(c), first_step_s=p["first"],
                   status="ok", **(p["metrics"] or {}))
        row["error"] = row.get(SCENES[key].error)
        rows.append(row)
    return rows


def speed_scene(key, configs, plan, engines=(), budget_s=None, progress=None, sweep=None, records=None):
    """Rows for every configuration (and one per reference engine) on scene ``key``, and the
    scene's source; ([], None) when the scene cannot be built.  The cases run on ``sweep``
    (bench/sweep.py: one timing case per one-thread worker; None: here, in turn), each into
    ``records`` as it finishes."""
    from .sweep import run_cases
    cases = speed_cases(key, configs, plan, engines, budget_s)
    if not cases:
        return [], None
    engines = scene_engines(key, engines)
    # the references' end figures are measured once per scene: in its first case
    cases = [dataclasses.replace(c, ref_metrics=bool(engines) and i == 0) for i, c in enumerate(cases)]
    outs = run_cases(sweep, run_speed_case, cases, speed_key, progress, records,
                     label=lambda c: f"{key}: {c.config.label}")
    rows, pooled = [], {e: {"chunks": [], "first": None, "metrics": None} for e in engines}
    for out in outs:
        rows.append(out["row"])
        for e, r in out["refs"].items():
            pooled[e]["chunks"] += r["chunks"]
            if pooled[e]["first"] is None:
                pooled[e]["first"] = r["first"]
            if r["metrics"] is not None:
                pooled[e]["metrics"] = r["metrics"]
    gc.collect()
    sd = cases[0].scene
    rows += reference_rows(key, plan, sd.desc["world"]["dt"], sd.source, engines, pooled)
    return rows, sd.source


def speed_key(case) -> str:
    """A speed case's name in a results file."""
    return f"speed {case.scene.key} {case.config.label} steps={case.plan.steps}"
