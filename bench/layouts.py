"""soft_step's two contact layouts timed against each other, interleaved (issue 17).

    python -m bench.layouts pyramid20 rain1000 large_pyramid suite:washer suite:many_pyramids

For each scene: one world per ``solver_layout`` ("rows", "coloured") on the identical scene
(bench/scenes.py; ``large_pyramid`` is Box2D v3's benchmark pyramid, base 100, 5,050 boxes;
``suite:NAME`` a scene of Box2D v3's benchmark suite, built and scripted as bench.suite_speed does),
warmed up, then chunks of steps alternating rows, coloured, coloured, rows, ...  Reported: the
median ms/step of each, wall clock and process CPU time (the CPU time leaves out the time the
process waited for a core: the machine may be shared), and the median of the per-chunk ratios
coloured / rows, so noise that hits both in one round cancels.
"""
from __future__ import annotations

import statistics
import sys
import time

from .desc import with_world
from .engines.ours import build_ours_world
from .scenes import BENCH_WORLD, GENERATORS, scene_data

LAYOUTS = ("rows", "coloured")
# (steps per chunk, warm-up steps, rounds) per scene
PLAN = {"pyramid20": (30, 60, 31), "rain1000": (30, 120, 21), "large_pyramid": (5, 40, 31)}


def scene(key) -> dict:
    if key == "large_pyramid":
        return with_world(GENERATORS["pyramid"](base=100), **BENCH_WORLD)
    return scene_data(key).desc


def _build(key):
    """Something to ``step()`` and its ``world``: a bench world, or a suite scene's simulation."""
    if key.startswith("suite:"):
        from .suite import SUITE
        from .suite_speed import _ours
        return _ours(SUITE[key[len("suite:"):]]())
    return _Plain(build_ours_world(scene(key)))


class _Plain:
    """A bench world as the suite's simulations look: ``step()`` and ``world``."""

    def __init__(self, world):
        self.world, self.step = world, world.step


def measure(key, chunk, warm, rounds) -> dict:
    """{layout: (wall ms/step, cpu ms/step)} and the ratios, medians over the rounds."""
    worlds = {}
    for name in LAYOUTS:
        w = worlds[name] = _build(key)
        w.world.settings["solver_layout"] = name
        for _ in range(warm):
            w.step()
    wall = {n: [] for n in LAYOUTS}
    cpu = {n: [] for n in LAYOUTS}
    for r in range(rounds):
        for name in (LAYOUTS if r % 2 == 0 else LAYOUTS[::-1]):
            w = worlds[name]
            t, c = time.perf_counter(), time.process_time()
            for _ in range(chunk):
                w.step()
            wall[name].append((time.perf_counter() - t) / chunk * 1e3)
            cpu[name].append((time.process_time() - c) / chunk * 1e3)
    med = statistics.median
    return {"wall": {n: med(wall[n]) for n in LAYOUTS}, "cpu": {n: med(cpu[n]) for n in LAYOUTS},
            "ratio_wall": med(a / b for a, b in zip(wall["coloured"], wall["rows"])),
            "ratio_cpu": med(a / b for a, b in zip(cpu["coloured"], cpu["rows"]))}


def main(argv=None) -> int:
    for key in (argv if argv is not None else sys.argv[1:]) or list(PLAN):
        chunk, warm, rounds = PLAN.get(key, (6, 60, 9) if key.startswith("suite:") else (20, 60, 21))
        m = measure(key, chunk, warm, rounds)
        print(f"{key}: rows {m['wall']['rows']:.3f} ms/step ({m['cpu']['rows']:.3f} cpu), coloured "
              f"{m['wall']['coloured']:.3f} ({m['cpu']['coloured']:.3f} cpu); coloured / rows "
              f"{m['ratio_wall']:.3f} wall, {m['ratio_cpu']:.3f} cpu ({rounds} rounds of {chunk} steps)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
