"""``python -m bench.prototypes.table_pass``: what passing a table between kernels costs.

Twelve stage kernels, each six read-modify-writes per row over four rows of a 26-field table,
called in turn by one compiled driver, with the table as (a) a namedtuple of 26 column arrays,
(b) the store's compact ``TableType`` (store/table_type.py: its two arrays, fields made on
access) and (c) one 2-D array indexed with column constants by hand.  Each variant runs in a
new process without a cache: the compile's CPU seconds, then ns per driver call in a compiled
loop and from Python.  docs/flat-step.md quotes the figures.
"""
from __future__ import annotations

import subprocess
import sys

import numpy as np

NFLD = 26
KERNELS = 12
ROWS = 4


def _sources(variant: str) -> tuple[list[str], str]:
    """The kernels' and the driver's source for a variant (B[i, c] or B.f[i, k] reads)."""
    def acc(k, f):
        return f"B[i, {2 * f + k}]" if variant == "2d" else f"B.f{f}[i, {k}]"
    kernels = []
    for s in range(KERNELS):
        body = "\n".join(f"        {acc(0, (s + j) % NFLD)} += 0.5 * {acc(1, (s + 2 * j + 1) % NFLD)} + h"
                         for j in range(6))
        kernels.append(f"def k{s}(B, n, h):\n    for i in range(n):\n{body}\n")
    driver = "def drv(B, n, h):\n" + "".join(f"    k{s}(B, n, h)\n" for s in range(KERNELS))
    return kernels, driver


def _table(variant: str):
    from collections import namedtuple

    from physics.store.table import allocate
    from physics.store.table_view import view_class
    spec = {f"f{i}": ((2,), np.float64) for i in range(NFLD)}
    cols = allocate(spec, ROWS)
    cols.F[:] = np.random.default_rng(0).random(cols.F.shape)
    if variant == "2d":
        return cols.F
    if variant == "nt":
        return namedtuple("T", list(spec))(**cols)
    return view_class("T", spec, "table_pass")(**cols)


def measure(variant: str) -> dict:
    """Compile CPU s and ns per call of one variant (run in a process of its own)."""
    import time

    from numba import njit
    inner = dict(no_cpython_wrapper=True, no_cfunc_wrapper=True, _nrt=False)
    ns: dict = {}
    kernels, driver = _sources(variant)
    for s, src in enumerate(kernels):
        exec(src, ns)
        ns[f"k{s}"] = njit(**inner)(ns[f"k{s}"])
    exec(driver, ns)
    drv = njit(_nrt=False)(ns["drv"])

    @njit(_nrt=False)
    def loop(B, n, h, reps):
        for _ in range(reps):
            drv(B, n, h)

    tab = _table(variant)
    t = time.process_time()
    drv(tab, ROWS, 0.01)
    loop(tab, ROWS, 0.01, 1)
    compile_s = time.process_time() - t
    reps = 200_000
    t = time.perf_counter()
    loop(tab, ROWS, 0.01, reps)
    in_loop = (time.perf_counter() - t) / reps * 1e9
    t = time.perf_counter()
    for _ in range(reps // 10):
        drv(tab, ROWS, 0.01)
    from_python = (time.perf_counter() - t) / (reps // 10) * 1e9
    return {"compile_cpu_s": compile_s, "ns_in_loop": in_loop, "ns_from_python": from_python}


def main() -> int:
    if len(sys.argv) > 2 and sys.argv[1] == "--one":
        print(measure(sys.argv[2]))
        return 0
    for variant, what in (("nt", "namedtuple of 26 arrays"), ("tt", "TableType"), ("2d", "one 2-D array")):
        p = subprocess.run([sys.executable, "-m", "bench.prototypes.table_pass", "--one", variant],
                           capture_output=True, text=True)
        r = eval(p.stdout.strip().splitlines()[-1]) if p.returncode == 0 else p.stderr[-300:]
        print(f"{what:>26s}: {r}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
