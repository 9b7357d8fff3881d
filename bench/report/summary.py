"""The summary lines on the targets (terminal and docs): ratios to pymunk, pybox2d and Box2D v3
(measured in the same run), the sub-step cost fit, scaling slopes, overhead and start-up."""
from __future__ import annotations

import numpy as np

from ..configs import DEFAULT_MODE
from ..engines import REF_ENGINES
from ..scaling import loglog_slope
from .tables import fmt


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


def summary_lines(res) -> list[str]:
    """Human-readable lines on the targets (used by the terminal and the docs)."""
    return [*_ratio_lines(res), *_substep_lines(res), *_scaling_lines(res), *_overhead_lines(res),
            *_startup_lines(res)]


def _ratio_lines(res):
    L = []
    sp = res.get("speed", [])
    for key in ("pyramid20", "pyramid40", "rain1000"):
        r = next((x for x in sp if x["scene"] == key and x["engine"] == "stelkropp" and x.get("default")
                  and x["mode"] == DEFAULT_MODE), None)
        pm = next((x for x in sp if x["scene"] == key and x["engine"] == "pymunk"), None)
        if not r or r.get("ms_step") is None:
            continue
        rp = r.get("ratio_pymunk")
        txt = (f"{key}: {DEFAULT_MODE} {r['ms_step']:.3f} ms/step = {fmt(rp, 2)}x pymunk"
               f" ({fmt(pm and pm.get('ms_step'))} ms), {fmt(r.get('ratio_pybox2d'), 2)}x pybox2d")
        if rp is not None and key in ("pyramid20", "rain1000"):
            txt += " -- target (<= pymunk) " + ("MET" if rp <= 1.0 else "NOT MET")
        b3 = next((x for x in sp if x["scene"] == key and x["engine"] == "box2d_v3"), None)
        if r.get("ratio_box2d_v3") is not None:
            txt += (f"; {r['ratio_box2d_v3']:.2f}x Box2D v3 ({fmt(b3 and b3.get('ms_step'))} ms, "
                    "measured in this run)")
        else:
            why = (res.get("meta", {}).get("engines_skipped") or {}).get("box2d_v3")
            txt += f"; Box2D v3 not measured ({why or 'not part of this run: python -m bench times it'})"
        L.append(txt)
    return L


def _substep_lines(res):
    L = []
    sp = res.get("speed", [])
    for key in ("pyramid20", "pyramid40", "rain1000"):
        f = substep_fit(sp, key)
        if f and f[1] <= 0:
            L.append(f"{key}: {DEFAULT_MODE} costs {f[0]:.3f} ms per sub-step (the fixed part is within the noise)")
        elif f:
            a, b, d = f
            L.append(f"{key}: {DEFAULT_MODE} costs {a:.3f} ms per sub-step + {b:.3f} ms per step "
                     f"(collision, contact preparation, restitution, overhead); at the default {d} sub-steps "
                     f"the sub-steps are {100 * a * d / (a * d + b):.0f}% of the step")
    return L


def _scaling_lines(res):
    L = []
    sc = res.get("scaling", [])
    if sc:
        for e in ("stelkropp", *REF_ENGINES):
            s = loglog_slope(sc, e)
            if s is not None:
                L.append(f"scaling {e}: ms/step ~ n^{s:.2f} from {sc[0]['n']} to {sc[-1]['n']} bodies")
    return L


def _overhead_lines(res):
    L = []
    ov = res.get("overhead")
    if ov:
        e = ov["empty_world_us"]
        L.append(f"world.step() overhead, empty world: {e:.2f} us (target < 20 us: {'MET' if e < 20 else 'NOT MET'}); "
                 f"1 body ({DEFAULT_MODE}): {fmt(ov['one_body_us'].get(DEFAULT_MODE), 1)} us; "
                 f"box on ground: {fmt(ov['box_on_ground_us'].get(DEFAULT_MODE), 1)} us")
        kc = ov.get("kernel_call")
        if kc:
            L.append("kernel call from Python: " + ", ".join(
                f"{k} ({v['arrays']} arrays) {v['us_per_call']:.2f} us" for k, v in kc.items()))
    return L


def _startup_lines(res):
    L = []
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
