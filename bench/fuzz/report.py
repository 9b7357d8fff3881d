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
        "by_mode": dict(Counter(c.get("mode", "none") for c in cases)),
        "failures": [dict(c, case=i) for i, c in enumerate(cases) if c["outcome"] in BAD][:50],
    }


def section(s: dict) -> str:
    """The Markdown section for a summary."""
    o = s["outcomes"]
    bad = {k: o.get(k, 0) for k in ("crash", "silent_nonfinite", "energy_gain", "slow")}
    stages = ", ".join(f"{k} {v}" for k, v in sorted(s["refused_by_stage"].items())) or "none"
    lines = [
        BEGIN, "## World fuzzer (last long run)", "",
        f"`python -m bench.fuzz --cases {s['cases']} --seed {s['seed']}` ({s['seconds']:.0f} s, peak RSS "
        f"{s['peak_rss_mb']} MB): random worlds of 1-6 bodies (boxes, circles, regular polygons of 1 cm - "
        "10 m; densities 1e-6..1e6 kg/m^2; speeds to 1e5 m/s; spin to 1e3 rad/s), 0-3 springs (k to 1e9 N/m, "
        "off-centre anchors), dt 1e-5..1 s, every mode, half the cases switching mode mid-run, 5-30 steps "
        "(bench/fuzz/). Invariants (bench/fuzz/check.py): only ValueError (building) or SimulationError "
        "naming its stage with world.fault set; no non-finite state or energy after an accepted step; "
        "the total energy never above E0 plus the energy present at the start (plus a push-out allowance "
        "of 1/2 m (n 10 m/s)^2 when bodies start inside each other); no case over 60 s.", "",
        "| cases | accepted runs | refused steps (SimulationError) | ValueError | crashes | silent non-finite "
        "| energy gains | slow |",
        "|---|---|---|---|---|---|---|---|",
        f"| {s['cases']} | {o.get('ok', 0)} | {o.get('refused', 0)} ({stages}) | {o.get('value_error', 0)} | "
        f"{bad['crash']} | {bad['silent_nonfinite']} | {bad['energy_gain']} | {bad['slow']} |", "",
    ]
    if s["failures"]:
        lines.append("Failing cases (outcome, mode, detail):")
        lines.append("")
        lines += [f"- case {f['case']}: {f['outcome']}, {f.get('mode', '?')}: {f.get('detail', '')}"
                  for f in s["failures"][:20]]
        lines.append("")
    lines.append(END)
    return "\n".join(lines)


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
