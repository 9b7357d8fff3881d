"""The benchmarks' independent cases on Dask (issue 19), through the tuner's plumbing
(physics/tuning/sweep.py: Sweep; physics/tuning/records.py: Records), not a second pool.

No scheduler: a LocalCluster of one worker process per core, each with one thread; an address:
that cluster; ``"inline"``: this process, one case after another.  A worker runs one case at a
time, so a timing case (speed: ours interleaved with the references chunk by chunk) never shares
its worker with another case; accuracy and reliability cases (figures, not timings) run side by
side on the workers like any other task.  The figures are bit-identical wherever a case runs
(deterministic physics); the timings are the worker's.

With a results file each finished case is appended (JSON lines, flushed) as it arrives, and with
``resume`` the cases already in it are not run again; the header (the physics source hash and
the run's options) refuses a file from another build or other options.
"""
from __future__ import annotations

import json

from physics.tuning.records import Records
from physics.tuning.sweep import Sweep

__all__ = ["Sweep", "open_records", "plain", "run_cases"]


def plain(x):
    """``x`` as JSON data (numpy scalars and arrays to Python numbers and lists; NaN kept)."""
    return json.loads(json.dumps(x, default=_default))


def _default(o):
    if hasattr(o, "tolist"):
        return o.tolist()
    if hasattr(o, "item"):
        return o.item()
    raise TypeError(f"not JSON data: {type(o).__name__}")


def open_records(path, tool: str, options: dict, resume: bool, encode=plain, decode=None):
    """A Records journal at ``path`` for ``tool``'s run with ``options`` (None path: None)."""
    if path is None:
        return None
    from physics._jit import _source_hash
    header = {"stelkropp": tool, "version": 1, "physics": _source_hash(), **plain(options)}
    return Records(path, header, resume, encode=encode, decode=decode)


def run_cases(sweep, fn, cases, key, progress=None, records=None, label=None) -> list:
    """``[fn(case) for case in cases]`` on ``sweep`` (a Sweep, or None: here, in order), results
    in the cases' order; ``progress`` (a tqdm bar) advances as each arrives, ``records`` gets it."""
    def arrived(case, result):
        if progress is not None:
            if label is not None:
                progress.set_description(label(case)[:60])
            progress.update(1)
    if sweep is None:
        sweep_here = Sweep("inline", progress=False)
        return sweep_here.map(fn, cases, desc="cases", journal=records, key=key, on_result=arrived)
    return sweep.map(fn, cases, desc="cases", journal=records, key=key, on_result=arrived)
