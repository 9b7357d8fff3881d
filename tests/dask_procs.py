"""A real Dask cluster on localhost for the sweep tests (issue 19): a ``dask scheduler`` process
and worker processes (``dask worker --no-nanny --nthreads 1``), started and stopped by the test.

Without a nanny a killed worker stays dead, so a test that kills one sees a lost worker, not a
restarted one.  The processes run this checkout (PYTHONPATH) and the test's numba cache.
"""
from __future__ import annotations

import contextlib
import json
import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
START_SECONDS = 60  # the workers import physics and numpy: seconds on a loaded 2-core machine


def _env() -> dict:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), *filter(None, [env.get("PYTHONPATH")])])
    return env


@contextlib.contextmanager
def dask_cluster(tmp_path, workers: int = 2):
    """Yield (scheduler address, {worker pid: Popen}); every process is stopped on exit."""
    sched_file = tmp_path / "scheduler.json"
    procs = []
    log = open(tmp_path / "dask.log", "w")
    try:
        procs.append(subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler", "--host",
                                       "127.0.0.1", "--port", "0", "--no-dashboard", "--scheduler-file",
                                       str(sched_file)], env=_env(), cwd=ROOT, stdout=log, stderr=log))
        address = _wait_address(sched_file, procs[0])
        for i in range(workers):
            procs.append(subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker", address,
                                           "--nthreads", "1", "--no-nanny", "--no-dashboard", "--name", f"w{i}",
                                           "--host", "127.0.0.1", "--death-timeout", "30"],
                                          env=_env(), cwd=ROOT, stdout=log, stderr=log))
        _wait_workers(address, workers)
        yield address, {p.pid: p for p in procs[1:]}
    finally:
        for p in reversed(procs):
            if p.poll() is None:
                p.terminate()
        for p in procs:
            try:
                p.wait(10)
            except subprocess.TimeoutExpired:
                p.kill()
        log.close()


def _wait_address(path: Path, proc) -> str:
    t0 = time.monotonic()
    while time.monotonic() - t0 < START_SECONDS:
        if proc.poll() is not None:
            raise RuntimeError(f"dask scheduler exited {proc.returncode}")
        try:
            return json.loads(path.read_text())["address"]
        except (OSError, ValueError, KeyError):
            time.sleep(0.1)
    raise RuntimeError("dask scheduler did not start")


def _wait_workers(address: str, n: int) -> None:
    from dask.distributed import Client
    with Client(address, timeout="30s") as client:
        client.wait_for_workers(n, timeout=START_SECONDS)


def worker_pids(client) -> dict:
    """{worker address: its process id} of the workers connected to ``client``'s scheduler."""
    return client.run(os.getpid)
