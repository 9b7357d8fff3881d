"""``python -m bench.scene_limits``: how long the loader and the geometry take at the limits a scene
may ask for (physics/scene/budget.py), against their targets.

- ``physics.decompose`` of 10,000-vertex outlines (a star and a noisy ring), and its growth from
  2,000 to 4,000 vertices (near-linear: well under the 4x of a quadratic cost);
- a 100,000-point chain added, then saved and loaded;
- ``python -m physics validate`` on files near the work limit (four 10,000-vertex outlines,
  200,000 circles: refused by the count, one 100,000-point chain): each under 10 s.

Each figure is the best of ``--repeat`` runs.  Results: stdout, and bench/results/scene_limits.md.
"""
from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "bench" / "results" / "scene_limits.md"
VALIDATE_TARGET = 10.0  # s: any scene under the file limit


def star(n, inner=0.6):
    a = np.linspace(0, 2 * math.pi, n, endpoint=False)
    r = np.where(np.arange(n) % 2 == 0, 1.0, inner)
    return np.c_[r * np.cos(a), r * np.sin(a)]


def noisy(n, seed=1):
    rng = np.random.default_rng(seed)
    a = np.sort(rng.uniform(0, 2 * math.pi, n))
    r = rng.uniform(0.5, 1.0, n)
    return np.c_[r * np.cos(a), r * np.sin(a)]


def best(fn, repeat):
    out = math.inf
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        out = min(out, time.perf_counter() - t)
    return out


def scene(bodies):
    return {"format": "stelkropp.scene", "version": 2, "bodies": bodies}


def big_files():
    chain = [[float(-i), math.sin(i)] for i in range(100_000)]
    return {
        "four 10k-vertex outlines": scene([{"shape": {"concave": star(10_000).tolist()}, "position": [3.0 * i, 0]}
                                           for i in range(4)]),
        "200,000 circles (refused)": scene([{"shape": {"circle": 0.5}, "position": [i % 1000, i // 1000]}
                                            for i in range(200_000)]),
        "one 100k-point chain": scene([{"kind": "static", "position": [0, 0], "shape": {"chain": {"points": chain}}}]),
    }


def measure(repeat: int = 3) -> list[tuple[str, float, str]]:
    import physics
    rows = []
    for name, make in (("star", star), ("noisy ring", noisy)):
        outline = make(10_000)
        rows.append((f"decompose, 10,000-vertex {name}", best(lambda: physics.decompose(outline), repeat), "s"))
    small, large = star(2_000), star(4_000)
    ratio = best(lambda: physics.decompose(large), repeat) / best(lambda: physics.decompose(small), repeat)
    rows.append(("decompose growth, 2,000 -> 4,000 vertices (quadratic: 4)", ratio, "x"))
    pts = np.c_[np.arange(100_000.0)[::-1], np.sin(np.arange(100_000.0))]
    rows.append(("100k-point chain: add", best(lambda: physics.World().add_body(physics.Chain(pts), kind="static"),
                                                 repeat), "s"))
    with tempfile.TemporaryDirectory() as tmp:
        w = physics.World()
        w.add_body(physics.Chain(pts), kind="static")
        path = Path(tmp) / "chain.json"

        def round_trip():
            w.save_scene(path)
            physics.load_scene(path)
        rows.append(("100k-point chain: save and load", best(round_trip, repeat), "s"))
        for name, data in big_files().items():
            p = Path(tmp) / "big.json"
            p.write_text(json.dumps(data))
            cmd = [sys.executable, "-m", "physics", "validate", str(p)]
            rows.append((f"validate: {name} (target {VALIDATE_TARGET:g} s)",
                         best(lambda: subprocess.run(cmd, cwd=ROOT, capture_output=True), repeat), "s"))
    return rows


def render(rows) -> str:
    lines = ["| what | best of runs |", "|---|---|"]
    lines += [f"| {name} | {value:.2f} {unit} |" for name, value, unit in rows]
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-write", action="store_true", help="print only")
    args = ap.parse_args(argv)
    table = render(measure(args.repeat))
    print(table)
    if not args.no_write:
        OUT.write_text("# Scene limits: loader and geometry at the work budget\n\n"
                       "`python -m bench.scene_limits` (best of runs, this machine).\n\n" + table + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
