"""The table of Box2D v3's benchmark suite run (bench/suite_speed.py), for the terminal and the docs."""
from __future__ import annotations

from .tables import fmt

# the engine labels of a suite row ("stelkropp": one thread, World.threads = 1)
OURS, OURS2, B1, B2, PM = "stelkropp", "stelkropp 2 threads", "box2d_v3 1 thread", "box2d_v3 2 threads", "pymunk"


def _bodies(r) -> str:
    """Bodies at the start, and at the end when a script changed them (rain: "1->1101")."""
    end = r.get("bodies_end")
    return f"{r['bodies']}->{end}" if end is not None and end != r["bodies"] else str(r["bodies"])


def table_md(rows) -> list[str]:
    """Markdown lines: one row per scene, ms/step per engine, our one-thread ratio to each, our
    two threads' ratio to Box2D v3 with one and with two, and what two threads gain us."""
    hdr = ["scene", "bodies", "steps", "stelkropp 1T ms", "stelkropp 2T ms", "Box2D v3 1T ms", "Box2D v3 2T ms",
           "pymunk ms", "1T x Box2D 1T", "2T x Box2D 1T", "2T x Box2D 2T", "1T x pymunk", "our 2T speedup",
           "status"]
    L = ["| " + " | ".join(hdr) + " |", "|" + "---|" * len(hdr)]
    for r in rows:
        ms, ra, r2 = r.get("ms_step", {}), r.get("ratio", {}), r.get("ratio_2t", {})
        st = r["status"]
        if st == "stelkropp cannot build it yet":
            st = "not built: " + (r["not_built"].get(OURS, "") or "; ".join(r["needs"]))
        elif r.get("needs"):
            st += "; differs: " + "; ".join(r["needs"])
        if r.get("not_built", {}).get(PM):
            st += "; no pymunk: " + r["not_built"][PM].split(": ", 1)[-1]
        L.append("| " + " | ".join(str(x) for x in [
            r["scene"], _bodies(r), r.get("steps_done", "-"), fmt(ms.get(OURS)), fmt(ms.get(OURS2)), fmt(ms.get(B1)),
            fmt(ms.get(B2)), fmt(ms.get(PM)), fmt(ra.get(B1), 2), fmt(r2.get(B1), 2), fmt(r2.get(B2), 2),
            fmt(ra.get(PM), 2), fmt(r.get("two_thread_speedup"), 2), st]) + " |")
    return L
