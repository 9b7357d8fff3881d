"""The run's report on the terminal."""
from __future__ import annotations

import sys

from ..profile import format_profile
from .summary import summary_lines
from .tables import accuracy_table, fmt, speed_table, text_table


def print_report(res, file=sys.stdout):
    """The speed, scaling, accuracy and profile tables and the summary, as text."""
    hdr, rows = speed_table(res.get("speed", []))
    print("\nSpeed (median ms/step; x ref = ours / ref per chunk, interleaved; error per scene: "
          "pyramids top-box drift m, rain max penetration m)", file=file)
    print(text_table(hdr, rows), file=file)
    if res.get("scaling"):
        print("\nScaling (columns of 10 boxes)", file=file)
        sh = ["n", "engine", "ms/step", "x pymunk", "x pybox2d", "x Box2D v3"]
        print(text_table(sh, [[r["n"], r["engine"], fmt(r["ms_step"]), fmt(r.get("ratio_pymunk"), 2),
                               fmt(r.get("ratio_pybox2d"), 2), fmt(r.get("ratio_box2d_v3"), 2)]
                              for r in res["scaling"]]), file=file)
    if res.get("accuracy"):
        print("\nAccuracy (defaults, dt 1/60; error: relative or absolute as per metric, ideal 0)", file=file)
        ah, ar = accuracy_table(res["accuracy"])
        print(text_table(ah, ar), file=file)
    if res.get("profile"):
        print("", file=file)
        for k, p in res["profile"].items():
            print(format_profile(k, p), file=file)
    print("", file=file)
    for ln in summary_lines(res):
        print(ln, file=file)
