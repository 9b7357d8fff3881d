"""The shipped many-shape scenes' speed in soft_step beside pymunk, in one interleaved run (issue 13).

    python -m bench.shape_speed                          # compounds, tumbler, cup, capsules, terrain
    python -m bench.shape_speed --scenes compounds --steps 120 --out /tmp/ss

Each scene of ``bench.scenes.SHAPE_BENCH`` (its shipped file; sleeping off) runs in Stelkropp's
soft_step defaults and in pymunk (every fixture as its Chipmunk shape: rounded polygons, offset
circles, capsules as radius segments, chains as segments with neighbours;
bench/engines/pymunk_shapes.py), chunk by chunk in turn, timed as ``bench.joint_speed`` times the
joint scenes.  Writes ``shape_speed.json`` and ``shape_speed.md`` into ``--out`` (default
bench/results/).
"""
from __future__ import annotations

import argparse
import json
from pathlib import Path

from .joint_speed import measure
from .paths import RESULTS
from .report.tables import fmt
from .scenes import SHAPE_BENCH


def table_md(rows) -> list[str]:
    """The markdown table of ``measure``'s rows (fixtures instead of joints)."""
    hdr = ["scene", "bodies", "fixtures", "steps", "soft_step ms", "pymunk ms", "x pymunk", "first step s", "status"]
    L = ["| " + " | ".join(hdr) + " |", "|" + "---|" * len(hdr)]
    for r in rows:
        L.append("| " + " | ".join(str(x) for x in [
            f"`{r['scene']}`", r["bodies"], r["fixtures"], r["steps"], fmt(r["ms_ours"]), fmt(r["ms_pymunk"]),
            fmt(r["ratio"], 2), fmt(r["first_step_s"], 2), r["status"]]) + " |")
    return L


def main(argv=None) -> int:
    """``python -m bench.shape_speed``: measure, write the JSON and the table, print it."""
    ap = argparse.ArgumentParser(prog="python -m bench.shape_speed", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenes", default=",".join(SHAPE_BENCH), help="comma-separated many-shape scenes")
    ap.add_argument("--steps", type=int, default=None, help="steps per scene (default: the scene's plan, 300)")
    ap.add_argument("--out", type=Path, default=RESULTS)
    a = ap.parse_args(argv)
    names = a.scenes.split(",")
    bad = [n for n in names if n not in SHAPE_BENCH]
    if bad:
        ap.error(f"unknown many-shape scene: {', '.join(bad)} (known: {', '.join(SHAPE_BENCH)})")
    rows = measure(names, a.steps, prefix="shapes")
    a.out.mkdir(parents=True, exist_ok=True)
    (a.out / "shape_speed.json").write_text(json.dumps(rows, indent=1) + "\n")
    md = "\n".join(table_md(rows)) + "\n"
    (a.out / "shape_speed.md").write_text(md)
    print(md)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
