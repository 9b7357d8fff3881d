"""``python -m bench.timeline_cost [--bodies 1000]``: what the sandbox's timeline (app.timeline)
costs on a big scene: the memory of a full ring (60 s at one snapshot per 0.25 s: 241
snapshots) and the time of a snapshot (taken once every 15 steps at 60 Hz) and of a scrub.

The world is bench.snapshot's pile (sleeping off, the contact tables full).  The ring is filled
with one step between snapshots (the sizes do not depend on how far apart they are) and its
memory is measured with tracemalloc (what the snapshots allocate), cross-checked against the
pickled size.  Timings belong in a benchmark, not in the unit tests.
"""
from __future__ import annotations

import argparse
import pickle
import statistics
import time
import tracemalloc

from bench.snapshot import pile


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bodies", type=int, default=1000)
    args = ap.parse_args(argv)
    from app.timeline import Timeline
    w = pile(args.bodies)
    tl = Timeline()
    from app.timeline import nbytes
    cap = tl.entries.maxlen
    take, steps = [], []
    tracemalloc.start()
    before = tracemalloc.get_traced_memory()[0]
    for _ in range(cap):
        t = time.perf_counter()
        w.step()
        steps.append(time.perf_counter() - t)
        t = time.perf_counter()
        tl.entries.append((w.time, w.snapshot()))      # what Timeline.record appends when one is due
        take.append(time.perf_counter() - t)
    ring = tracemalloc.get_traced_memory()[0] - before
    tracemalloc.stop()
    pickled = len(pickle.dumps(tl.entries[-1][1]))
    counted = nbytes(tl.entries[-1][1])      # what the ring's budget counts (app.timeline.BUDGET)
    scrub = []
    for k in range(0, cap, 10):
        t = time.perf_counter()
        tl.scrub(w, tl.entries[k][0])
        scrub.append(time.perf_counter() - t)
    ms = lambda xs: 1e3 * statistics.median(xs)  # noqa: E731
    step_ms = ms(steps)
    print(f"{args.bodies} bodies: ring of {cap} snapshots = {ring / 2**20:.1f} MiB "
          f"({ring / cap / 1024:.0f} KiB each; pickled {pickled / 1024:.0f} KiB; array bytes {counted / 1024:.0f} KiB)")
    print(f"snapshot {ms(take):.2f} ms (median; one per 15 steps at 60 Hz: {ms(take) / 15:.3f} ms a step, "
          f"{100 * ms(take) / 15 / step_ms:.1f} % of a {step_ms:.1f} ms step); scrub (restore) {ms(scrub):.2f} ms")


if __name__ == "__main__":
    main()
