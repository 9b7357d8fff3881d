"""The tuner's sweep on a real Dask cluster started by the test on localhost (issue 19): a
``dask scheduler`` and two one-thread ``dask worker`` processes (tests/dask_procs.py).

The cases are a fixed list (round one of two modes on a 3-body scene, 16 steps) so the result
sets can be compared whole: round two of ``tune`` depends on timings, these do not."""
import numpy as np

from dask_procs import dask_cluster, worker_pids
from test_tune import small_scene

from physics.tuning import candidates as grid
from physics.tuning import runs
from physics.tuning.sweep import Sweep

STEPS, STRIDE = 16, 8
FIELDS = ("positions", "angles", "kinetic", "potential", "speeds", "links", "pins", "sizes")


def _cases():
    return [grid.REFERENCE] + grid.round_one(["soft_step", "sequential_impulse"])


def _same(a, b) -> bool:
    """Two runs' records are equal bit for bit (timings aside)."""
    return (a.key, a.depth, a.steps, a.error) == (b.key, b.depth, b.steps, b.error) and all(
        getattr(a, f).shape == getattr(b, f).shape and np.array_equal(getattr(a, f), getattr(b, f))
        for f in FIELDS)


def _inline(cases):
    with Sweep("inline", progress=False) as sw:
        return sw.map(runs.task, cases, small_scene(), STEPS, STRIDE)


def test_sweep_through_a_scheduler_address_equals_the_local_run(tmp_path):
    cases = _cases()
    with dask_cluster(tmp_path) as (address, _):
        with Sweep(address, progress=False) as sw:
            remote = sw.map(runs.task, cases, small_scene(), STEPS, STRIDE)
            assert sw.where == f"Dask scheduler {address}"
            ran_on = set(worker_pids(sw._client).values())
    local = _inline(cases)
    assert len(ran_on) == 2 and len(remote) == len(cases) > 10
    assert all(_same(a, b) for a, b in zip(remote, local))


def test_a_worker_killed_mid_sweep_costs_only_its_cases(tmp_path):
    cases = _cases()
    killed = {}
    with dask_cluster(tmp_path) as (address, procs):
        with Sweep(address, progress=False) as sw:
            client = sw._client
            pids = worker_pids(client)
            assert set(pids.values()) == set(procs)  # the workers are the processes this test started

            def kill_a_busy_worker(case, result):
                if killed:
                    return
                busy = {w: ks for w, ks in client.processing().items() if ks}
                victim = sorted(busy)[0]  # a worker holding cases not yet finished
                killed.update(address=victim, holding=len(busy[victim]))
                procs[pids[victim]].kill()
                procs[pids[victim]].wait(10)
            remote = sw.map(runs.task, cases, small_scene(), STEPS, STRIDE, on_result=kill_a_busy_worker)
            left = client.scheduler_info()["workers"]
    # the victim held unfinished cases when it died, and the scheduler knows it is gone
    assert killed["holding"] >= 1 and killed["address"] not in left and len(left) == 1
    # every case finished anyway (Dask reran the lost ones on the other worker), bit for bit as here
    local = _inline(cases)
    assert len(remote) == len(cases) and all(r is not None for r in remote)
    assert all(_same(a, b) for a, b in zip(remote, local))
