"""``python -m bench.small_scenes``: the small scenes most people build, beside pymunk.

The five generated scenes of bench/small_descs.py and the shipped pendulum, double pendulum,
Newton's cradle, car and piston, each in Stelkropp's soft_step defaults and in pymunk (10
iterations), timed chunk by chunk in turn in one process (bench/speed.py), sleeping off:
us/step the median of the timed chunks, ``x pymunk`` the median of the per-chunk ratios, the
first step (compile or cache load) apart.  The target is at most 1.0x pymunk on every row.
Writes ``small_scenes.json`` and ``small_scenes.md`` into ``--out`` (default bench/results/).
"""
from __future__ import annotations

import argparse
import json
from pathlib import Path

from .joint_speed import measure
from .paths import RESULTS
from .report.tables import fmt
from .small_descs import SMALL

SHIPPED = ("pendulum", "double_pendulum", "newtons_cradle", "car", "piston")


def table_md(rows) -> list[str]:
    hdr = ["scene", "bodies", "joints", "steps", "soft_step us", "pymunk us", "x pymunk", "first step s"]
    out = ["| " + " | ".join(hdr) + " |", "|" + "---|" * len(hdr)]
    for r in rows:
        us = [None if r[k] is None else 1e3 * r[k] for k in ("ms_ours", "ms_pymunk")]
        out.append("| " + " | ".join(str(x) for x in [
            f"`{r['scene']}`", r["bodies"], r["joints"], r["steps"], fmt(us[0], 1), fmt(us[1], 1),
            fmt(r["ratio"], 1), fmt(r["first_step_s"], 2)]) + " |")
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m bench.small_scenes", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--steps", type=int, default=None, help="steps per scene (default: 3000 generated, 300 shipped)")
    ap.add_argument("--out", type=Path, default=RESULTS)
    a = ap.parse_args(argv)
    shipped = measure(list(SHIPPED), a.steps, prefix="joints")
    for r in shipped:  # the shipped files by their file names (a generated pendulum is beside them)
        r["scene"] = f"scenes/{r['scene']}.json"
    rows = measure(list(SMALL), a.steps, prefix="small") + shipped
    a.out.mkdir(parents=True, exist_ok=True)
    (a.out / "small_scenes.json").write_text(json.dumps(rows, indent=1) + "\n")
    md = "\n".join(table_md(rows)) + "\n"
    (a.out / "small_scenes.md").write_text(md)
    print(md)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
