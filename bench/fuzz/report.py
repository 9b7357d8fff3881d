"""The fuzz run's counts: bench/results/fuzz_world.json and the "World fuzzer" section of docs/reliability.md."""
from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

from ..paths import RELIABILITY_DOC, RESULTS

RESULT = RESULTS / "fuzz_world.json"
BEGIN = "<!-- world fuzzer: written by python -m bench.fuzz -->"
END = "<!-- end of world fuzzer -->"


def summarise(cases: list[dict], seed: int, seconds: float, peak_mb: float) -> dict:
    """Counts by outcome, refusals by stage, value errors, and the failing cases (at most 50)."""
    from .check import BAD
    return {
        "cases": len(cases), "seed": seed, "seconds": round(seconds, 1), "peak_rss_mb": round(peak_mb),
        "outcomes": dict(Counter(c["outcome"] for c in cases)),
        "refused_by_stage": dict(Counter(c.get("stage", "?") for c in cases if c["outcome"] == "refused")),
        "refused_by_reason": dict(Counter(c.get("reason", "?") for c in cases if c["outcome"] == "refused")),
        "energy_guard_by_mode": dict(Counter(c.get("mode", "?") for c in cases if c.get("reason") == "energy_guard")),
        "by_mode": dict(Counter(c.get("mode", "none") for c in cases)),
        "failures": [dict(c, case=i) for i, c in enumerate(cases) if c["outcome"] in BAD][:50],
        **gains(cases),
    }


#: the issue's aim: no accepted gain above 1 % of the starting energy scale without input
GAIN_AIM = 0.01


def gains(cases: list[dict]) -> dict:
    """Per mode, the largest accepted gain (E - E0) / starting energy scale of the cases without a
    motor or mouse joint (check.EnergyBound), the cases above GAIN_AIM and the worst ten; also
    split by how the world started (bodies separated, or overlapping: push-out's allowance)."""
    free = [(i, c) for i, c in enumerate(cases) if c.get("gain_mode") and not c.get("driven")]
    split: dict = {"separated": {}, "overlapping": {}}   # per start, mode -> (largest gain, cases over)
    for _, c in free:
        part = split["overlapping" if c.get("overlapping") else "separated"]
        big, n = part.get(c["gain_mode"], (0.0, 0))
        part[c["gain_mode"]] = (max(big, c["gain"]), n + (c["gain"] > GAIN_AIM))
    top, over = {}, Counter()
    for part in split.values():
        for m, (big, n) in part.items():
            top[m] = max(top.get(m, 0.0), big)
            over[m] += n
    worst = sorted(free, key=lambda ic: -ic[1]["gain"])[:10]
    return {"largest_gain_by_mode": {k: float(f"{v:.4g}") for k, v in sorted(top.items())},
            "gains_over_aim_by_mode": {m: n for m, n in sorted(over.items()) if n},
            "gains_by_start": {k: {m: [float(f"{g:.4g}"), n] for m, (g, n) in sorted(v.items())}
                               for k, v in split.items()},
            "worst_gains": [{"case": i, "mode": c["gain_mode"], "gain": float(f"{c['gain']:.4g}"),
                             "dt": c.get("dt"), "overlapping": c.get("overlapping")} for i, c in worst]}


def gains_table(by_start: dict) -> list[str]:
    """Markdown rows: per start, per mode, the largest gain and (in brackets) the cases above the aim."""
    modes = sorted({m for v in by_start.values() for m in v})
    rows = ["| start | " + " | ".join(modes) + " |", "|---|" + "---|" * len(modes)]
    for start, v in by_start.items():
        rows.append(f"| {start} | " + " | ".join(f"{v[m][0]:.3g} ({v[m][1]})" if m in v else "-" for m in modes)
                    + " |")
    return rows + [""]


def section(s: dict) -> str:
    """The Markdown section for a summary."""
    o = s["outcomes"]
    bad = {k: o.get(k, 0) for k in ("crash", "silent_nonfinite", "energy_gain", "slow")}
    stages = ", ".join(f"{k} {v}" for k, v in sorted(s.get("refused_by_reason", s["refused_by_stage"]).items())) \
        or "none"
    lines = [
        BEGIN, "## World fuzzer (last long run)", "",
        f"`python -m bench.fuzz --cases {s['cases']} --seed {s['seed']}` ({s['seconds']:.0f} s, peak RSS "
        f"{s['peak_rss_mb']} MB): random worlds of 1-6 bodies (boxes, circles, regular polygons of 1 cm - "
        "10 m; densities 1e-6..1e6 kg/m^2; speeds to 1e5 m/s; spin to 1e3 rad/s), 0-3 springs (k to 1e9 N/m, "
        "off-centre anchors), 0-2 joints of every kind (limits, springs to 1e3 Hz, motors, breakable), "
        "dt 1e-5..1 s, every mode, half the cases switching mode mid-run, 5-30 steps (bench/fuzz/). "
        "Invariants (bench/fuzz/check.py): only ValueError (building) or SimulationError naming its stage "
        "with world.fault set; no non-finite state or energy after an accepted step; without a motor or "
        "mouse joint, the total energy never above the energy guard's stated bound E0 + (S0 + S/2) + "
        "push-out allowance + noise floor (physics/step/energy_guard.py), computed independently; no case over 60 s. "
        "Refused steps are counted by reason (energy_guard: the guard refused a step that gained "
        "energy; substeps: a spring or contact too stiff for max_substeps; nonfinite).", "",
        "| cases | accepted runs | refused steps (SimulationError) | ValueError | crashes | silent non-finite "
        "| energy gains | slow |",
        "|---|---|---|---|---|---|---|---|",
        f"| {s['cases']} | {o.get('ok', 0)} | {o.get('refused', 0)} ({stages}) | {o.get('value_error', 0)} | "
        f"{bad['crash']} | {bad['silent_nonfinite']} | {bad['energy_gain']} | {bad['slow']} |", "",
    ]
    guard = s.get("energy_guard_by_mode") or {}
    lines += [
        "What holds: every accepted step is finite and inside the energy bound; a step that would "
        "gain more is reverted and raised by the energy guard (SimulationError at 'solve', world.fault "
        "set; world.energy_guard = 0 turns it off). The guard is a net, not a cure: the steps it "
        "refused are real energy gains of the solvers at these extremes (by mode: "
        + (", ".join(f"{k} {v}" for k, v in sorted(guard.items())) or "none") + "). Known sources: "
        "in penalty, a fast-spinning disc that crosses a body within one step (the fuzzer's 16.6 g disc "
        "at 3.7 km/s into a 1 m slab, dt 0.023 s: 8.5 x its energy with the guard off; the contact "
        "point's arm is turned with the body, 3.3 rad in that step, so a frictionless contact on a disc "
        "exerts a torque; tests/test_contact_energy.py). The issue's own item-2 repros (a 1.7 g box into "
        "a 3 kg box at 1000 m/s, x1053 then; densities 0.026 and 8e5, 3e24x then) now gain nothing in any "
        "mode with the guard turned off (largest E/E0 over 60 steps 0.032 and 0.99999; "
        "test_the_issue_repros_gain_nothing_without_the_guard). Also stiff springs on tiny bodies moving "
        "far within one step in "
        "soft_step (e.g. seed 1 case 102: 2.7e8 N/m on 0.58 mg at 2,078 m/s, dt 0.115 s; the implicit "
        "solve is linearised at the step start). The sequential_impulse, impulse and soft_step contact "
        "gains are not yet diagnosed. Fixed at the source since: several penalty points loading one body "
        "beyond what the sub-steps integrate (coincident points of a compound's overlapping fixtures: "
        "Box2D's compounds scene gained 4.5e6 J in one step in penalty); "
        "physics/solvers/classic/penalty_load.py scales those contacts back to the stability bound "
        "(tests/test_penalty_load.py).", ""]
    if "largest_gain_by_mode" in s:
        lines += ["Largest accepted gain (E - E0) / starting energy scale per mode, cases without a motor or "
                  "mouse joint (E: kinetic + gravity from the start + springs, computed by the fuzzer; the aim "
                  f"is {GAIN_AIM:.0%}): " + ", ".join(f"{k} {v:.3g}" for k, v in s["largest_gain_by_mode"].items())
                  + "; cases above the aim: " + (", ".join(f"{k} {v}" for k, v in
                                                          sorted(s["gains_over_aim_by_mode"].items())) or "none")
                  + ". By how the world started (overlapping: push-out may add the energy of separating "
                  "the overlap, physics/step/push_out.py), the largest gain and the cases above the aim:", ""]
        lines += gains_table(s.get("gains_by_start", {}))
    if s["failures"]:
        lines.append("Failing cases (outcome, mode, detail):")
        lines.append("")
        lines += [f"- case {f['case']}: {f['outcome']}, {f.get('mode', '?')}: {f.get('detail', '')}"
                  for f in s["failures"][:20]]
        lines.append("")
    lines.append(END)
    return "\n".join(lines)


def write_partial(s: dict, planned: int) -> None:
    """The counts of an unfinished run (``planned`` cases) beside the results."""
    RESULT.parent.mkdir(parents=True, exist_ok=True)
    RESULT.with_suffix(".partial.json").write_text(json.dumps(dict(s, planned=planned), indent=1) + "\n")


def load() -> dict | None:
    return json.loads(RESULT.read_text()) if RESULT.exists() else None


def write(s: dict, doc: Path = RELIABILITY_DOC) -> None:
    """Save the summary and replace (or append) the section in the docs page."""
    RESULT.parent.mkdir(parents=True, exist_ok=True)
    RESULT.write_text(json.dumps(s, indent=1) + "\n")
    text = doc.read_text() if doc.exists() else ""
    if BEGIN in text and END in text:
        head, rest = text.split(BEGIN, 1)
        text = head + section(s) + rest.split(END, 1)[1]
    else:
        text = text.rstrip("\n") + "\n\n" + section(s) + "\n"
    doc.write_text(text)
