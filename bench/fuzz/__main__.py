"""``python -m bench.fuzz --cases N [--seed S] [--jobs J] [--no-write]``: the world fuzzer with a
progress bar; ``--jobs`` runs the cases in J processes (each case is seeded by its number, so the
counts do not depend on J)."""
from __future__ import annotations

import argparse
import functools
import multiprocessing
import resource
import sys
import time

from tqdm import tqdm

from .check import BAD, run_case, warm_up
from .report import section, summarise, write, write_partial


def main(argv=None) -> int:
    """Run N cases; print the section; write the results and docs unless --no-write.
    Returns 1 when any case broke an invariant."""
    ap = argparse.ArgumentParser(description="world fuzzer (issue 20): random extreme worlds in every mode")
    ap.add_argument("--cases", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=1, help="worker processes (default 1)")
    ap.add_argument("--partial", type=int, default=0, metavar="K",
                    help="every K cases write the counts so far to bench/results/fuzz_world.partial.json")
    ap.add_argument("--no-write", action="store_true", help="print only; keep the results and docs")
    a = ap.parse_args(argv)
    cases = []
    one = functools.partial(run_case, base=a.seed)
    warm_up()  # compiled once here: forked workers inherit the kernels
    t0 = time.perf_counter()
    pool = multiprocessing.get_context("fork").Pool(a.jobs) if a.jobs > 1 else None
    results = pool.imap(one, range(a.cases), chunksize=8) if pool else map(one, range(a.cases))
    bar = tqdm(results, total=a.cases, desc="world fuzz", unit="case")
    for i, case in enumerate(bar):
        cases.append(case)
        if case["outcome"] in BAD:
            bar.write(f"case {i}: {case['outcome']}: {case.get('detail', '')}")
        if a.partial and (i + 1) % a.partial == 0:  # a long run's counts so far survive an interrupt
            write_partial(summarise(cases, a.seed, time.perf_counter() - t0, 0.0), a.cases)
    if pool:
        pool.close()
        pool.join()
    peak = max(resource.getrusage(who).ru_maxrss for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)) / 1024.0
    s = summarise(cases, a.seed, time.perf_counter() - t0, peak)
    print(section(s))
    if not a.no_write:
        write(s)
    return 1 if any(c["outcome"] in BAD for c in cases) else 0


if __name__ == "__main__":
    sys.exit(main())
