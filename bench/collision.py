"""Collision benchmark: broad phase ms per call, narrow phase pairs per second.

    python -m bench.collision [--quick]

Broad phase: every method on random boxes in a square region and on a packed
pyramid over a wide static ground box, 1k and 10k bodies, plus a sweep over
small counts that locates where brute force stops paying (the "auto"
crossover).  Narrow phase: ``physics.collision.narrowphase.collide`` over many
separated, overlapping pairs of one shape combination, per method.
The first call of each kernel (numba compile, or loading its cache) is
reported apart from the timings.  Results also go to
bench/results/collision.json.
"""
from __future__ import annotations

import argparse
import json
import math
import platform
import time
from pathlib import Path

import numpy as np

from physics import Circle, Polygon, World
from physics.collision import broadphase, narrowphase
from physics.options import NARROWPHASES
from physics.step.context import StepContext
from physics.store import ContactBuffer
from physics.store import BODY_FIELDS, STATIC, Bodies, allocate

RESULTS = Path(__file__).resolve().parent / "results" / "collision.json"
BROAD_METHODS = ("brute", "sweep", "quadtree")
BRUTE_MAX = 3000          # brute force beyond this takes seconds per call
MARGIN = 0.01             # AABB fattening, like a resting scene's speculative margin


# -- broad-phase scenes: only the AABB, kind and awake columns matter --------
def random_boxes(n, seed=0):
    """Boxes 0.5..1.5 m in a square holding about two boxes per 3 m^2."""
    rng = np.random.default_rng(seed)
    B = Bodies(**allocate(BODY_FIELDS, max(n, 1)))
    side = math.sqrt(n) * 1.6
    c = rng.uniform(0, side, (n, 2))
    h = rng.uniform(0.25, 0.75, (n, 2))
    B.aabb[:n, :2] = c - h
    B.aabb[:n, 2:] = c + h
    B.awake[:n] = 1
    return B, n


def pyramid(n):
    """1 m boxes stacked in a pyramid (rows offset by half a box) on a static
    ground 20x wider than the base; n counts the ground too."""
    base = max(1, int((math.sqrt(8 * (n - 1) + 1) - 1) / 2))
    boxes = [(-10.0 * base, -1.0, 10.0 * base, 0.0)]
    for row in range(base):
        for k in range(base - row):
            x, y = 0.5 * row + k, float(row)
            boxes.append((x, y, x + 1.0, y + 1.0))
    boxes = np.array(boxes[:n]) + (-MARGIN, -MARGIN, MARGIN, MARGIN)
    m = len(boxes)
    B = Bodies(**allocate(BODY_FIELDS, m))
    B.aabb[:m] = boxes
    B.kind[0] = STATIC
    B.awake[:m] = 1
    return B, m


def time_call(fn, min_time=0.2, min_reps=3):
    """Median seconds per call over batches filling about ``min_time``."""
    t0 = time.perf_counter()
    fn()
    once = max(time.perf_counter() - t0, 1e-7)
    reps = max(min_reps, int(min_time / once / 5))
    batches = []
    for _ in range(5):
        t0 = time.perf_counter()
        for _ in range(reps):
            fn()
        batches.append((time.perf_counter() - t0) / reps)
    return float(np.median(batches))


def broad_compile():
    B, n = random_boxes(50)
    out = {}
    for m in BROAD_METHODS:
        t0 = time.perf_counter()
        broadphase.find_pairs(B, n, m, np.zeros((8, 2), np.int32))
        out[m] = time.perf_counter() - t0
    return out


def broad_timings(sizes, min_time):
    rows = []
    for scene, make in (("random", random_boxes), ("pyramid", pyramid)):
        for size in sizes:
            B, n = make(size)
            row = {"scene": scene, "bodies": n}
            for m in BROAD_METHODS:
                if m == "brute" and n > BRUTE_MAX:
                    row[m] = None
                    continue
                pairs = np.zeros((16, 2), np.int32)
                count, pairs = broadphase.find_pairs(B, n, m, pairs)
                row["pairs"] = count
                row[m] = 1e3 * time_call(lambda: broadphase.find_pairs(B, n, m, pairs), min_time)
            rows.append(row)
    return rows


def crossover(rows):
    """Smallest body count from which sweep beats brute in every scene."""
    worst = {}
    for r in rows:
        if r["brute"] is not None:
            worst.setdefault(r["bodies"], []).append(r["sweep"] < r["brute"])
    wins = sorted(n for n, ok in worst.items() if all(ok))
    losses = [n for n, ok in worst.items() if not all(ok)]
    later = [n for n in wins if n > max(losses, default=0)]
    return later[0] if later else None


# -- narrow phase ---------------------------------------------------------
def narrow_world(kind, npairs):
    """``npairs`` overlapping pairs, each alone (no broad phase needed), at
    assorted angles so SAT and GJK see every feature combination."""
    rng = np.random.default_rng(1)
    w = World(gravity=(0.0, 0.0))
    shapes = {
        "box-box": (Polygon.box(1.0, 1.0), Polygon.box(1.0, 1.0)),
        "poly8-poly8": (Polygon.regular(8, 0.6), Polygon.regular(8, 0.6)),
        "circle-poly": (Circle(0.5), Polygon.box(1.0, 1.0)),
    }[kind]
    for k in range(npairs):
        x = 4.0 * (k % 100)
        y = 4.0 * (k // 100)
        d = rng.uniform(0.75, 0.95)
        t = rng.uniform(0, 2 * math.pi)
        w.add_body(shapes[0], position=(x, y), angle=rng.uniform(0, 2 * math.pi))
        w.add_body(shapes[1], position=(x + d * math.cos(t), y + d * math.sin(t)),
                   angle=rng.uniform(0, 2 * math.pi))
    w._pipeline.refresh_geometry(w, 1 / 60)
    pairs = np.arange(2 * npairs, dtype=np.int32).reshape(npairs, 2)
    return w, pairs


def narrow_timings(npairs, min_time):
    rows, compile_s = [], {}
    for kind in ("box-box", "poly8-poly8", "circle-poly"):
        w, pairs = narrow_world(kind, npairs)
        B, F, V, spec = w._bodies.view, w._store.fixtures.view, w._verts.view, w.speculative_distance
        row = {"pair": kind, "pairs": npairs}
        for method in NARROWPHASES:
            contacts = ContactBuffer()
            ctx = StepContext()
            ctx.set("dt", 1 / 60)
            ctx.set("spec", spec)
            ctx.set("narrowphase", NARROWPHASES.index(method))
            t0 = time.perf_counter()
            rows_made = narrowphase.collide(ctx, B, F, V, pairs, npairs, contacts)
            compile_s[method] = max(compile_s.get(method, 0.0), time.perf_counter() - t0)
            sec = time_call(lambda: narrowphase.collide(ctx, B, F, V, pairs, npairs, contacts), min_time)
            row[method] = npairs / sec
            row[method + "_manifolds"] = rows_made
        rows.append(row)
    return rows, compile_s


# -- report ---------------------------------------------------------------
def _ms(x):
    return "      -" if x is None else f"{x:7.3f}"


def print_report(res):
    print("compile / cache load, first call (s):",
          ", ".join(f"{k} {v:.2f}" for k, v in {**res["broad_compile_s"],
                                                  **res["narrow_compile_s"]}.items()))
    print("\nbroad phase, ms per call")
    print(f"{'scene':8} {'bodies':>7} {'pairs':>7} " + " ".join(f"{m:>8}" for m in BROAD_METHODS))
    for r in res["broad"]:
        print(f"{r['scene']:8} {r['bodies']:7d} {r['pairs']:7d} "
              + " ".join(f" {_ms(r[m])}" for m in BROAD_METHODS))
    print(f"\nauto crossover (sweep beats brute from): {res['crossover']} bodies "
          f"(broadphase.AUTO_BRUTE_BELOW = {broadphase.AUTO_BRUTE_BELOW})")
    print(f"\nnarrow phase, pair tests per second ({res['narrow'][0]['pairs']} pairs per call)")
    print(f"{'pair':12} {'sat':>12} {'gjk':>12}")
    for r in res["narrow"]:
        print(f"{r['pair']:12} {r['sat']:12,.0f} {r['gjk']:12,.0f}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="shorter timing runs")
    args = ap.parse_args(argv)
    min_time = 0.05 if args.quick else 0.3
    res = {"machine": platform.platform(), "python": platform.python_version()}
    res["broad_compile_s"] = broad_compile()
    small = broad_timings([8, 16, 32, 48, 64, 96, 128, 192, 256, 384, 512], min_time / 3)
    res["crossover"] = crossover(small)
    res["broad_small"] = small
    res["broad"] = broad_timings([1000, 10000], min_time)
    res["narrow"], res["narrow_compile_s"] = narrow_timings(2000, min_time)
    print_report(res)
    RESULTS.parent.mkdir(parents=True, exist_ok=True)
    RESULTS.write_text(json.dumps(res, indent=1))
    print(f"\nwrote {RESULTS.relative_to(Path.cwd()) if RESULTS.is_relative_to(Path.cwd()) else RESULTS}")


if __name__ == "__main__":
    main()
