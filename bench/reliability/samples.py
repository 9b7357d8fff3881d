"""Box2D v3's Stacking / Robustness samples and issue 18's cases in Stelkropp, beside Box2D v3.

    python -m bench.reliability --samples [--only card_house] [--box2d-live] [--set substeps=8 ...]

Each sample of ``bench.suite.samples`` runs in Stelkropp's default mode (soft_step, its default
settings, dt 1/60, the sub-steps the world chooses: 4, or 8 for thin or small bodies, sleeping
off) and the figure functions of ``bench/box2d/figures_*.py`` measure it exactly as they measure Box2D v3.  Box2D's figures come
from ``bench/results/box2d_v3_figures.json`` (the same descriptions, ``python -m
bench.box2d.samples``) or, with ``--box2d-live``, from Box2D v3 run in the same process.
``COMPARE`` says per figure what "at least as steady as Box2D v3" means.  Stelkropp builds each
sample through its scene loader (``bench.engines.ours.scene_world``): the same segments,
capsules, rounded boxes, several shapes per body and joints as Box2D v3; only the ``box2d`` keys
(Box2D's own contact and joint tuning, rolling resistance) are Box2D's alone.

``--set key=value`` (repeatable) runs Stelkropp with those soft_step settings instead of its
defaults, to measure what a setting does to every figure (bench/results/issue18_experiments.md);
a run with settings is printed, never written to the docs.
"""
from __future__ import annotations

import json
import sys
import time

import numpy as np

from ..box2d.figures_cases import CASE_FIGURES
from ..box2d.figures_samples import SAMPLE_FIGURES
from ..engines.ours import OursSim, scene_world
from ..paths import RESULTS
from ..suite import measures as M
from ..suite.samples import SAMPLES

FIGURES_JSON = RESULTS / "box2d_v3_figures.json"
# figure id -> how ours is judged against Box2D v3's value b (None: shown, not judged)
#   "lower": |ours| <= max(|b| * 1.05, floor)   (a displacement, sink, speed: less is steadier)
#   ("ideal", x): |ours - x| <= |b - x| * 1.05 or within 5 % of x
#   ("target", bound): |ours| < bound (issue 18's targets where Box2D gives none)
#   "equal": ours == b (counts)
COMPARE = {
    "single_box.slide_distance": ("ideal", 5.0 ** 2 / 12.0), "single_box.height_error": "lower",
    "single_box.max_tilt": "lower",
    "vertical_stack.top_displacement_10s": "lower",
    "circle_stack.height_error_10s": "lower", "circle_stack.drift_10s": "lower",
    "cliff.landed_5s": "equal", "cliff.max_upward_speed": "lower",
    "arch.creep_2_20s": "lower",
    "double_domino.fallen_10s": "equal",
    "confined.outside_10s": "equal", "confined.max_speed_8_10s": "lower",
    "card_house.top_displacement_10s": "lower", "card_house.max_card_displacement_10s": "lower",
    "high_mass_ratio_1.top_displacement_10s_max": "lower",
    "high_mass_ratio_2.big_sink_10s": "lower", "high_mass_ratio_3.big_sink_10s": "lower",
    "overlap_recovery.max_push_speed": "lower", "overlap_recovery.top_height_error_10s": "lower",
    "tiny_pyramid.top_displacement_10s": "lower", "high_mass_ratio_1.rest_displacement_10s": "lower",
    "multiple_prismatic.top_sag_10s": "lower", "multiple_prismatic.max_joint_separation_10s": "lower",
    "mass_ratio_1000.sink_4_5s": ("target", 0.05), "mass_ratio_1000.toppled_10s": ("target", 0.5),
    "restitution.worst_ratio": ("ideal", 1.0),
    "small_stack.sink_4s": ("target", 0.05),
}
for _sub in (4, 12):  # the cart's chassis sink, bounce and axle separation at 4 and 12 sub-steps
    for _fig in ("chassis_sink_10s", "chassis_vy_rms_5_10s", "max_joint_separation_5_10s"):
        COMPARE[f"cart.{_fig}.substeps{_sub}"] = "lower"
for _h in (0.2, 0.5, 1.0, 2.0, 5.0):
    for _tag in ("flat", "corner"):
        COMPARE[f"restitution.{_tag}.h{_h:g}"] = ("ideal", 0.25 * _h)
FLOOR = 1e-3  # below this (in the figure's unit) a "lower" figure counts as zero


def run_ours(name, seconds, substeps=None, scene_kw=None, settings=None):
    """(trace, description, sim) of a sample run for ``seconds`` in Stelkropp's default mode
    (``settings``: soft_step settings that replace its defaults). ``substeps`` is a figure's own
    sub-step count (the cart's ``substeps12`` figures name theirs in their id), so it wins over a
    ``substeps`` in ``settings``, which applies to the figures that ask for none (without either,
    the world's own choice: 4, or 8 for thin or small bodies, solvers/soft_step/fit.py)."""
    chosen = dict(settings or {})
    if substeps is not None:
        chosen["substeps"] = substeps
    desc = SAMPLES[name](**(scene_kw or {}))
    if "substeps" not in chosen:  # the default mode: the sub-steps the world chooses for the scene
        desc["world"].get("settings", {}).pop("substeps", None)
    sim = OursSim(desc, world=scene_world(desc, source=f"bench.suite {name}"), solver="soft_step",
                  settings=chosen)
    names = {b["name"]: i for i, b in enumerate(desc["bodies"]) if b.get("name")}
    return M.record(sim, seconds, names), desc, sim


def box2d_figures(live=False, only=None):
    """{figure id: value} of Box2D v3: recorded (``FIGURES_JSON``) or measured now (``live``)."""
    if live:
        from ..box2d.samples import measure
        return {f["id"]: f["value"] for f in measure(only)}
    return {f["id"]: f["value"] for f in json.loads(FIGURES_JSON.read_text())["figures"]}


def verdict(fid, ours, b2):
    """'yes' / 'no' / '' (not judged) for figure ``fid``: is ours at least as steady as Box2D v3?"""
    rule = COMPARE.get(fid)
    if rule is None or ours is None:
        return ""
    if rule == "lower":
        return "yes" if abs(ours) <= max(abs(b2) * 1.05, FLOOR) else "no"
    if rule == "equal":
        return "yes" if ours == b2 else "no"
    kind, x = rule
    if kind == "target":
        return "yes" if abs(float(ours)) < x else "no"
    ok = abs(ours - x) <= abs(b2 - x) * 1.05 or abs(ours - x) <= 0.05 * abs(x)
    return "yes" if ok else "no"


def parse_settings(pairs):
    """{name: value} of ``key=value`` strings, read as the physics CLI reads ``--set``
    (physics/cli.py ``parse_set_item``) and checked by soft_step's declared setting (its type,
    choices and bounds: physics/settings.py ``Setting.coerce``); a bad one is a ValueError naming it."""
    from physics.cli import parse_set_item
    from physics.solvers.soft_step.mode import SoftStep
    known = SoftStep.settings
    out = {}
    for kv in pairs or ():
        key, value = parse_set_item(kv, lambda k: k in known and known[k].type is bool)
        if key not in known:
            raise ValueError(f"--set {key}: not a soft_step setting (one of {', '.join(sorted(known))})")
        out[key] = known[key].coerce(value)
    return out


def measure_ours(only=None, progress=True, settings=None):
    """[(figure dict, seconds)] of every figure function (``only``: name filter) in Stelkropp
    (``settings``: soft_step settings replacing its defaults); one that fails is listed with
    ``value`` None and the error as its note."""
    out = []

    def run(name, seconds, substeps=None, scene_kw=None):
        return run_ours(name, seconds, substeps, scene_kw, settings)
    for f in SAMPLE_FIGURES + CASE_FIGURES:
        if only and only not in f.__name__:
            continue
        t0 = time.perf_counter()
        try:
            figs = f(run)
        except Exception as e:  # a sample the core cannot build yet is reported, not fatal
            out.append(({"id": f.__name__[4:] + ".*", "value": None, "unit": "", "scene": f.__name__[4:],
                         "note": f"not run: {type(e).__name__}: {e}"[:160]}, 0.0))
            continue
        dt = time.perf_counter() - t0
        for fig in figs:
            d = {"id": fig.id, "value": fig.value, "unit": fig.unit, "scene": fig.scene, "note": ""}
            out.append((d, dt))
        if progress:
            print(f"  {f.__name__:28s} {dt:6.1f} s", file=sys.stderr, flush=True)
    return out


def _fmt(v):
    if v is None:
        return "-"
    if isinstance(v, (bool, np.bool_)):
        return str(bool(v))
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    return f"{float(v):.4g}"


def rows(only=None, live=False, settings=None):
    """[(id, unit, box2d value, ours, verdict, note)] for the table."""
    b2 = box2d_figures(live, only)
    out = []
    for d, _ in measure_ours(only, settings=settings):
        v2 = b2.get(d["id"])
        out.append((d["id"], d["unit"], v2, d["value"], verdict(d["id"], d["value"], v2) if v2 is not None else "",
                    d["note"]))
    return out


def render_section(table, live, elapsed, settings=None):
    """The docs/reliability.md section (markdown lines) of ``rows()``."""
    held = sum(1 for r in table if r[4] == "yes")
    judged = sum(1 for r in table if r[4])
    src = "measured in the same run" if live else "from `bench/results/box2d_v3_figures.json`"
    lines = ["## Box2D v3's samples, side by side", "",
             "Generated by `python -m bench.reliability --samples` "
             f"({elapsed:.0f} s): each sample of `bench/suite/samples.py` (Box2D v3's `sample_stacking.cpp`, "
             "`sample_robustness.cpp` and issue 18's cases) in Stelkropp's default mode (soft_step, default "
             "settings, dt 1/60, the sub-steps the world chooses (4, or 8 for thin or small bodies: "
             "solvers/soft_step/fit.py), sleeping off), measured by the figure functions of "
             f"`bench/box2d/figures_*.py`; Box2D v3's values {src}. *steady* says whether ours is at least "
             "as steady as Box2D v3 on that figure (`bench/reliability/samples.py` COMPARE: within 5 % of "
             "Box2D's value or better; closer to the ideal; or issue 18's target where Box2D has none). "
             "Both engines build the same shapes and joints (Stelkropp through its scene loader); Box2D's "
             "own contact and joint tuning of a sample (`box2d` keys) is Box2D's alone. "
             f"**{held} of {judged}** judged figures hold. What was measured on the ones that do not: "
             "`bench/results/issue18_experiments.md` (re-run any setting with `--set NAME=VALUE`)."
             + (" Settings changed from the defaults: " + ", ".join(f"{k}={v}" for k, v in settings.items()) + "."
                if settings else ""), "",
             "| figure | unit | Box2D v3 | Stelkropp | steady | note |", "|---|---|---|---|---|---|"]
    for fid, unit, v2, v, ok, note in table:
        lines.append(f"| `{fid}` | {unit} | {_fmt(v2)} | {_fmt(v)} | {ok} | {note} |")
    return lines + [""]


BEGIN, END = "<!-- samples:begin -->", "<!-- samples:end -->"


def splice(doc: str, section: list[str]) -> str:
    """``doc`` with the text between the samples markers replaced (appended when absent)."""
    block = "\n".join([BEGIN, *section, END])
    if BEGIN in doc and END in doc:
        head, rest = doc.split(BEGIN, 1)
        return head + block + rest.split(END, 1)[1]
    return doc.rstrip("\n") + "\n\n" + block + "\n"


def main_samples(out, only=None, live=False, settings=None) -> int:
    """Run the samples, print the table and (unless ``only`` or ``settings``) splice it into ``out``."""
    t0 = time.perf_counter()
    table = rows(only, live, settings)
    section = render_section(table, live, time.perf_counter() - t0, settings)
    print("\n".join(section))
    if not only and not settings:
        from pathlib import Path
        p = Path(out)
        p.write_text(splice(p.read_text() if p.exists() else "", section))
        print(f"wrote {out}")
    return 0


def keep_section(path, doc: str) -> str:
    """``doc`` (the probes' page) with the samples section of the page at ``path`` kept."""
    old = path.read_text() if path.exists() else ""
    if BEGIN in old and END in old:
        return doc.rstrip("\n") + "\n\n" + BEGIN + old.split(BEGIN, 1)[1].split(END, 1)[0] + END + "\n"
    return doc
