"""``python -m bench.fuzz --cases N [--seed S] [--no-write]``: the world fuzzer with a progress bar."""
from __future__ import annotations

import argparse
import resource
import sys
import time

from tqdm import tqdm

from .check import BAD, run_case, warm_up
from .report import section, summarise, write


def main(argv=None) -> int:
    """Run N cases; print the section; write the results and docs unless --no-write.
    Returns 1 when any case broke an invariant."""
    ap = argparse.ArgumentParser(description="world fuzzer (issue 20): random extreme worlds in every mode")
    ap.add_argument("--cases", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--no-write", action="store_true", help="print only; keep the results and docs")
    a = ap.parse_args(argv)
    warm_up()
    t0 = time.perf_counter()
    cases = []
    bar = tqdm(range(a.cases), desc="world fuzz", unit="case")
    for i in bar:
        cases.append(run_case(i, a.seed))
        if cases[-1]["outcome"] in BAD:
            bar.write(f"case {i}: {cases[-1]['outcome']}: {cases[-1].get('detail', '')}")
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    s = summarise(cases, a.seed, time.perf_counter() - t0, peak)
    print(section(s))
    if not a.no_write:
        write(s)
    return 1 if any(c["outcome"] in BAD for c in cases) else 0


if __name__ == "__main__":
    sys.exit(main())
