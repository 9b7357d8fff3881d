"""Running independent cases as dask.distributed tasks, with a progress bar: the one Dask
plumbing of ``tune``, ``bench`` and ``bench.reliability`` (issue 19).

``scheduler=None`` starts a LocalCluster on this machine (a worker process of
one thread per core); an address (``tcp://host:8786``) uses that cluster;
``"inline"`` runs the cases one after another in this process (no Dask: for
the Python API inside a process that must not spawn workers).  Each worker
runs one case at a time on one thread, so a case's timing never shares its
core with another case on the same worker (issue 19: timings need a quiet
core); the workers themselves may still share the machine, which is why the
table's seconds are for ranking, not a benchmark.
"""
from __future__ import annotations

import os
import sys

class Cancelled(Exception):
    """The sweep's ``cancel`` callable returned True: the sweep stopped between cases."""


#: worker processes of a local cluster: one per core (each with one thread)
LOCAL_WORKERS = max(1, os.cpu_count() or 1)
CONNECT_SECONDS = 10


class Sweep:
    """A context manager that maps a function over cases on Dask (or inline); ValueError naming
    ``scheduler`` if the address cannot be reached, ImportError if dask[distributed] is missing.

    ``cancel``: a callable checked before each case and as each result arrives; once it returns
    True, ``map`` raises Cancelled (Dask futures not yet finished are cancelled).  ``on_progress``:
    called as ``on_progress(desc, done, total)`` when a map starts and after each case (the sandbox's
    Find settings button shows these)."""

    def __init__(self, scheduler: str | None = None, workers: int = LOCAL_WORKERS, progress: bool = True,
                 cancel=None, on_progress=None):
        self.scheduler = scheduler
        self.workers = workers
        self.progress = progress
        self.cancel = cancel
        self.on_progress = on_progress
        self._client = self._cluster = None

    def __enter__(self):
        if self.scheduler == "inline":
            return self
        try:
            from dask.distributed import Client, LocalCluster
        except ImportError:
            raise ImportError("the tuner runs its sweep on Dask: pip install 'stelkropp[tune]' "
                              "(dask[distributed]), or pass scheduler='inline'") from None
        if self.scheduler is None:
            self._cluster = LocalCluster(n_workers=self.workers, threads_per_worker=1, processes=True,
                                         dashboard_address=None)
            self._client = Client(self._cluster)
        else:
            if not isinstance(self.scheduler, str) or not self.scheduler:
                raise ValueError(f"scheduler: expected an address such as tcp://host:8786, got {self.scheduler!r}")
            try:
                self._client = Client(self.scheduler, timeout=f"{CONNECT_SECONDS}s")
            except (OSError, TimeoutError, ValueError, TypeError) as exc:
                raise ValueError(f"scheduler: cannot reach {self.scheduler} within {CONNECT_SECONDS} s "
                                 f"({type(exc).__name__}: {str(exc)[:200]})") from None
        return self

    def __exit__(self, *exc):
        if self._client is not None:
            self._client.close()
        if self._cluster is not None:
            self._cluster.close()
        return False

    @property
    def where(self) -> str:
        """Where the cases run, for the report."""
        if self.scheduler == "inline":
            return "inline (this process)"
        if self._cluster is not None:
            return f"Dask LocalCluster, {self.workers} worker{'s' * (self.workers != 1)} x 1 thread"
        return f"Dask scheduler {self.scheduler}"

    def map(self, fn, cases: list, *args, desc: str = "cases", journal=None, key=None, on_result=None) -> list:
        """``[fn(case, *args) for case in cases]``, run as Dask tasks; results in the cases' order.

        With a ``journal`` (records.Records), cases whose key (``key(case)``, default
        ``case.key``) it holds are not run again and each new result is appended to it as it
        finishes; ``on_result(case, result)`` is called as each one arrives (in this process)."""
        from tqdm import tqdm
        key = key or (lambda c: c.key)
        done = journal.done if journal is not None else {}
        out = [done.get(key(c)) for c in cases]
        todo = [i for i, r in enumerate(out) if r is None]
        bar = tqdm(total=len(cases), initial=len(cases) - len(todo), desc=desc, unit="case", file=sys.stderr,
                   disable=not (self.progress and sys.stderr.isatty()))

        count = [len(cases) - len(todo)]

        def finished(i, result):
            out[i] = result
            if journal is not None:
                journal.add(key(cases[i]), result)
            if on_result is not None:
                on_result(cases[i], result)
            bar.update()
            count[0] += 1
            self._report(desc, count[0], len(cases))
        try:
            self._report(desc, count[0], len(cases))
            if self._client is None:
                for i in todo:
                    self._check()
                    finished(i, fn(cases[i], *args))
                return out
            from dask.distributed import as_completed
            # pure=False: a case is timed, so an identical case must run again, not come from a cache
            futures = {self._client.submit(fn, cases[i], *args, pure=False): i for i in todo}
            try:
                for fut in as_completed(list(futures)):
                    self._check()
                    finished(futures[fut], fut.result())
            except Cancelled:
                self._client.cancel(list(futures))
                raise
            return out
        finally:
            bar.close()

    def _check(self) -> None:
        if self.cancel is not None and self.cancel():
            raise Cancelled("the sweep was cancelled")

    def _report(self, desc, done, total) -> None:
        if self.on_progress is not None:
            self.on_progress(desc, done, total)
