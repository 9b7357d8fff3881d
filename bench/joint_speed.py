"""The shipped joint scenes' speed in soft_step beside pymunk, in one interleaved run (issue 14).

    python -m bench.joint_speed                      # every joint scene, 300 steps each
    python -m bench.joint_speed --scenes car,walker --steps 120 --out /tmp/js

Each scene of ``bench.scenes.JOINT_BENCH`` (its shipped file; sleeping off) runs in Stelkropp's
soft_step defaults and in pymunk (its joints as Chipmunk constraints, bench/engines/
pymunk_joints.py), chunk by chunk in turn, as ``python -m bench`` times every scene
(bench/speed.py, bench/timing.py): ms/step the median of the timed chunks, ``x pymunk`` the
median of the per-chunk ratios, the first step (compile) apart.  Writes ``joint_speed.json`` and
``joint_speed.md`` into ``--out`` (default bench/results/); the table is quoted in
bench/results/notes.md, which docs/benchmarks.md includes.
"""
from __future__ import annotations

import argparse
import json
from pathlib import Path

from .configs import Config
from .paths import RESULTS
from .report.tables import fmt
from .scenes import JOINT_BENCH, SCENES, scene_data
from .speed import speed_scene


def measure(names, steps=None, prefix="joints") -> list[dict]:
    """One row per scene: bodies, joints, ms/step of both engines, the ratio, the first step
    (``prefix``: the bench scene family, ``joints_<name>`` or ``shapes_<name>``)."""
    cfg = Config("soft_step", {}, "soft_step", default=True)
    out = []
    for name in names:
        key = f"{prefix}_{name}"
        plan = dict(SCENES[key].full)
        if steps:
            plan.update(steps=steps, warm=min(plan["warm"], steps // 3))
        rows, _ = speed_scene(key, [cfg], plan, ("pymunk",))
        ours = next(r for r in rows if r["engine"] == "stelkropp")
        ref = next((r for r in rows if r["engine"] == "pymunk"), {})
        data = scene_data(key).data
        out.append(dict(scene=name, bodies=len(data["bodies"]), joints=len(data.get("joints", [])),
                        fixtures=sum(len(b.get("shapes", [0])) for b in data["bodies"]),
                        steps=ours.get("steps"), ms_ours=ours.get("ms_step"), ms_pymunk=ref.get("ms_step"),
                        ratio=ours.get("ratio_pymunk"), first_step_s=ours.get("first_step_s"),
                        status=ours.get("status")))
        print(f"{name:16s} {fmt(ours.get('ms_step'))} ms  pymunk {fmt(ref.get('ms_step'))} ms  "
              f"x{fmt(ours.get('ratio_pymunk'), 2)}  {ours.get('status')}", flush=True)
    return out


def table_md(rows, count="joints") -> list[str]:
    """The markdown table of ``measure``'s rows; ``count`` names the column of what each scene
    is made of (``joints``, or ``fixtures`` for bench.shape_speed)."""
    hdr = ["scene", "bodies", count, "steps", "soft_step ms", "pymunk ms", "x pymunk", "first step s", "status"]
    L = ["| " + " | ".join(hdr) + " |", "|" + "---|" * len(hdr)]
    for r in rows:
        L.append("| " + " | ".join(str(x) for x in [
            f"`{r['scene']}`", r["bodies"], r[count], r["steps"], fmt(r["ms_ours"]), fmt(r["ms_pymunk"]),
            fmt(r["ratio"], 2), fmt(r["first_step_s"], 2), r["status"]]) + " |")
    return L


def cli(argv, prog, doc, known, prefix, count) -> int:
    """The command line both scene families share: measure ``--scenes`` (of ``known``), write
    ``<prefix-stem>_speed.json`` and ``.md`` into ``--out``, print the table."""
    ap = argparse.ArgumentParser(prog=prog, description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenes", default=",".join(known), help="comma-separated scenes")
    ap.add_argument("--steps", type=int, default=None, help="steps per scene (default: the scene's plan, 300)")
    ap.add_argument("--out", type=Path, default=RESULTS)
    a = ap.parse_args(argv)
    names = a.scenes.split(",")
    bad = [n for n in names if n not in known]
    if bad:
        ap.error(f"unknown scene: {', '.join(bad)} (known: {', '.join(known)})")
    rows = measure(names, a.steps, prefix=prefix)
    stem = {"joints": "joint", "shapes": "shape"}[prefix]
    a.out.mkdir(parents=True, exist_ok=True)
    (a.out / f"{stem}_speed.json").write_text(json.dumps(rows, indent=1) + "\n")
    md = "\n".join(table_md(rows, count)) + "\n"
    (a.out / f"{stem}_speed.md").write_text(md)
    print(md)
    return 0


def main(argv=None) -> int:
    """``python -m bench.joint_speed``: measure, write the JSON and the table, print it."""
    return cli(argv, "python -m bench.joint_speed", __doc__, JOINT_BENCH, "joints", "joints")


if __name__ == "__main__":
    raise SystemExit(main())
