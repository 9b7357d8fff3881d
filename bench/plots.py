"""Matplotlib PNGs from a benchmark result dict (``bench/results/bench.json``).

    python -m bench.plots [RESULTS_DIR]     # re-plot from the saved json

* ``pareto_<scene>.png`` -- ms/step against the scene's error for every mode and setting,
  the pareto front (nothing both faster and more accurate) marked, pymunk and pybox2d as
  reference points.
* ``scaling.png`` -- ms/step against body count, log-log, with a linear reference.
* ``accuracy.png`` -- error of every accuracy metric, default settings per mode and the
  references (dt 1/60).
* ``profile.png`` -- where the default mode's step goes, per scene.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .profile import result_stages  # noqa: E402

MODE_COLORS = {"soft_step": "tab:blue", "sequential_impulse": "tab:orange", "impulse": "tab:green",
               "penalty": "tab:red", "hybrid": "tab:purple", "xpbd": "tab:brown"}
REF_STYLE = {"pymunk": dict(marker="*", color="black", s=180), "pybox2d": dict(marker="s", color="dimgray", s=90),
             "box2d_v3": dict(marker="D", color="tab:red", s=90)}
FLOOR = 1e-6  # errors below this are drawn at the floor (log axes)


def _color(mode):
    return MODE_COLORS.get(mode, "tab:gray")


def pareto_front(points):
    """Indices of points (x, y) not dominated by another (smaller x and smaller y are better)."""
    idx = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], np.inf
    for i in idx:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def pareto_plot(res, scene, path):
    rows = [r for r in res.get("speed", []) if r["scene"] == scene and r.get("ms_step") is not None
            and r.get("error") is not None]
    if not rows:
        return None
    meta = res.get("scenes", {}).get(scene, {})
    fig, ax = plt.subplots(figsize=(9, 6))
    ours = [r for r in rows if r["engine"] == "stelkropp"]
    pts = [(r["ms_step"], max(r["error"], FLOOR)) for r in ours]
    seen = set()
    for r, (x, y) in zip(ours, pts):
        bad = r.get("status", "ok") != "ok"
        lab = r["mode"] if r["mode"] not in seen else None
        seen.add(r["mode"])
        ax.scatter([x], [y], color=_color(r["mode"]), marker="x" if bad else ("D" if r.get("default") else "o"),
                   s=60 if r.get("default") else 30, label=lab, zorder=3)
        short = r["label"][len(r["mode"]):].strip() or "default"
        ax.annotate(short, (x, y), fontsize=6.5, xytext=(4, 3), textcoords="offset points", color=_color(r["mode"]))
    front = [i for i in pareto_front(pts) if ours[i].get("status", "ok") == "ok"]
    if front:
        fx, fy = zip(*sorted(pts[i] for i in front))
        ax.step(fx, fy, where="post", color="black", lw=1.0, ls="--", alpha=0.6, label="pareto front (ours)", zorder=2)
        ax.scatter(fx, fy, facecolors="none", edgecolors="black", s=140, lw=1.0, zorder=2)
    for r in rows:
        if r["engine"] in REF_STYLE:
            ax.scatter([r["ms_step"]], [max(r["error"], FLOOR)], label=r["label"], zorder=4, **REF_STYLE[r["engine"]])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("ms per step (median, lower is faster)")
    err = meta.get("error", "error")
    ax.set_ylabel({"top_drift": "top-box drift (m)", "max_penetration": "max penetration (m)"}.get(err, err)
                  + f" after {meta.get('steps', '?')} steps (lower is better)")
    ax.set_title(f"{meta.get('title', scene)}\nspeed vs error (diamond: default settings, x: failed or cut short)", fontsize=10)
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def scaling_plot(res, path):
    rows = res.get("scaling") or []
    if not rows:
        return None
    fig, ax = plt.subplots(figsize=(7, 5))
    for eng, style in (("stelkropp", dict(color="tab:blue", marker="o")),
                       ("pymunk", dict(color="black", marker="*")), ("pybox2d", dict(color="dimgray", marker="s")),
                       ("box2d_v3", dict(color="tab:red", marker="D"))):
        pts = sorted((r["n"], r["ms_step"]) for r in rows if r["engine"] == eng and r.get("ms_step"))
        if pts:
            x, y = zip(*pts)
            lab = eng if eng != "stelkropp" else f"stelkropp ({rows[0].get('mode', '')})"
            ax.plot(x, y, label=lab, **style)
    ours = sorted((r["n"], r["ms_step"]) for r in rows if r["engine"] == "stelkropp" and r.get("ms_step"))
    if ours:
        n0, t0 = ours[-1]  # through ours at the largest n: the fixed per-step cost bends small n
        xs = np.array([ours[0][0], ours[-1][0]], float)
        ax.plot(xs, t0 * xs / n0, color="tab:blue", ls=":", alpha=0.7, label=f"linear (through ours at n={n0})")
        ax.plot(xs, t0 * (xs / n0) ** 2, color="tab:red", ls=":", alpha=0.4, label="quadratic")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("bodies (1x1 boxes in columns of 10)")
    ax.set_ylabel("ms per step (median)")
    ax.set_title("Scaling with body count")
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def accuracy_plot(res, path):
    acc = [r for r in res.get("accuracy") or [] if r.get("default") and abs(r["dt"] - 1 / 60) < 1e-12
           and r.get("error") is not None]
    if not acc:
        return None
    metrics = list(dict.fromkeys(r["metric"] for r in acc))
    labels = list(dict.fromkeys(r["label"] for r in acc))
    ncol = 3
    nrow = int(np.ceil(len(metrics) / ncol))
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 0.35 * len(labels) * nrow + 1.2 * nrow), squeeze=False)
    for ax, m in zip(axes.flat, metrics):
        ys, xs, cs = [], [], []
        for i, lab in enumerate(labels):
            r = next((r for r in acc if r["metric"] == m and r["label"] == lab), None)
            if r is None:
                continue
            ys.append(i)
            xs.append(max(abs(r["error"]), FLOOR))
            cs.append(REF_STYLE[r["engine"]]["color"] if r["engine"] in REF_STYLE else _color(r["mode"]))
        ax.hlines(ys, FLOOR * 0.5, xs, colors=cs, lw=2, alpha=0.6)
        ax.scatter(xs, ys, c=cs, s=30, zorder=3)
        ax.set_xscale("log")
        ax.set_xlim(FLOOR * 0.5, max(max(xs) * 3, FLOOR * 10))
        ax.set_yticks(range(len(labels)))
        ax.set_yticklabels(labels, fontsize=7)
        unit = next((r["unit"] for r in acc if r["metric"] == m), "")
        ax.set_title(f"{m} ({'relative' if unit in ('rel', 's', 'm/s^2') and m not in ('pile_time_to_rest',) else unit})"
                     if m != "pile_time_to_rest" else "pile time to rest (s)", fontsize=8)
        ax.invert_yaxis()
        ax.grid(True, axis="x", which="major", alpha=0.3)
        ax.set_xlabel(f"error (values <= {FLOOR:g} at the left edge)", fontsize=6)
    for ax in list(axes.flat)[len(metrics):]:
        ax.axis("off")
    fig.suptitle("Accuracy against known answers (default settings, dt 1/60; shorter is better)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def profile_plot(res, path):
    prof = res.get("profile") or {}
    if not prof:
        return None
    stages = [*result_stages(next(iter(prof.values()))), "python/other"]
    fig, ax = plt.subplots(figsize=(8, 0.6 * len(prof) + 1.6))
    cmap = plt.get_cmap("tab10")
    for i, (scene, p) in enumerate(prof.items()):
        left = 0.0
        us = p["us_per_step"]
        for k, s in enumerate(stages):
            v = us.get(s, 0.0) / 1e3
            ax.barh([i], [v], left=left, color=cmap(k), label=s if i == 0 else None)
            left += v
    ax.set_yticks(range(len(prof)))
    ax.set_yticklabels(list(prof))
    ax.set_xlabel("ms per step")
    ax.set_title("Where the default mode's step goes")
    ax.legend(fontsize=7, ncol=4, loc="upper center", bbox_to_anchor=(0.5, -0.25))
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def make_all(res, outdir):
    outdir = Path(outdir)
    made = []
    for scene in dict.fromkeys(r["scene"] for r in res.get("speed", [])):
        p = pareto_plot(res, scene, outdir / f"pareto_{scene}.png")
        if p:
            made.append(p)
    for fn, name in ((scaling_plot, "scaling.png"), (accuracy_plot, "accuracy.png"), (profile_plot, "profile.png")):
        p = fn(res, outdir / name)
        if p:
            made.append(p)
    return made


if __name__ == "__main__":
    d = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent / "results"
    for p in make_all(json.loads((d / "bench.json").read_text()), d):
        print(p)
