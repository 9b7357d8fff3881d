"""The tuner's cancel hook and progress callback (issue 19: the sandbox's Find settings button
shows progress and stops on Cancel), and the sandbox's tuner process (app/tune_worker.py) that
uses them.  Tiny scene, one mode, 16 steps: a few seconds."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

import physics
from physics.tuning import Cancelled

from test_tune import counted, small_scene  # noqa: F401 (counted: a fixture)

ROOT = Path(__file__).resolve().parents[1]
KW = dict(steps=16, budget=0.05, modes=["soft_step"], scheduler="inline", progress=False)


def test_cancel_stops_the_search_between_runs(counted):
    # cancel once 5 runs have finished: the reference pair and 3 of round one
    with pytest.raises(Cancelled):
        physics.tune(small_scene(), cancel=lambda: len(counted) >= 5, **KW)
    assert len(counted) == 5     # checked before each run: not one more started


def test_cancel_before_anything_runs_nothing(counted):
    with pytest.raises(Cancelled):
        physics.tune(small_scene(), cancel=lambda: True, **KW)
    assert counted == []


def test_progress_counts_every_run_of_every_stage(counted):
    seen = []
    result = physics.tune(small_scene(), on_progress=lambda *a: seen.append(a), cancel=lambda: False, **KW)
    stages = [s for s, _, _ in seen]
    assert stages[0] == "reference" and "round 1" in stages and "round 2" in stages
    ends = {s: (d, t) for s, d, t in seen}            # each stage's last report: all of it done
    assert all(d == t for d, t in ends.values()), ends
    assert ends["reference"] == (2, 2)
    assert ends["round 1"][1] + ends["round 2"][1] == len(result.rows) == len(counted) - 2
    for s in ends:   # 0 at the start, then one more per run
        assert [d for st, d, _ in seen if st == s] == list(range(ends[s][1] + 1))


def _worker():
    return subprocess.Popen([sys.executable, "-m", "app.tune_worker"], cwd=ROOT, text=True,
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)


def _send(proc, **job):
    job = {"scene": small_scene(), "steps": 16, "metric": "trajectory", "budget": 0.05, **job}
    proc.stdin.write(json.dumps(job) + "\n")
    proc.stdin.flush()


def _records(proc) -> list:
    """The worker's lines up to its last one (stdin stays open: closing it means the sandbox is
    gone, which cancels the search).  Progress and compile records may come in any order before
    the last line."""
    recs = []
    for line in proc.stdout:
        recs.append(json.loads(line))
        if "progress" not in recs[-1] and "compile" not in recs[-1]:
            break
    proc.stdin.close()
    proc.wait(30)
    return recs


def _first_progress(proc) -> dict:
    """The worker's first line that is not a compile record (a cold cache compiles first)."""
    rec = json.loads(proc.stdout.readline())
    while "compile" in rec:
        rec = json.loads(proc.stdout.readline())
    return rec


def test_worker_reports_progress_and_a_choice_it_measured():
    proc = _worker()
    _send(proc, budget=0.5)
    recs = _records(proc)
    assert proc.returncode == 0, proc.stderr.read()
    assert any("progress" in r for r in recs) and "result" in recs[-1], recs[-3:]
    res = recs[-1]["result"]
    c = res["choice"]
    assert c["within"] and c["error"] <= 0.5
    # every setting of the chosen mode is reported, not only those the tuner varied
    w = physics.World(solver=c["solver"])
    assert set(c["settings"]) == set(w.settings.declared())
    assert res["baseline"]["key"] == "soft_step"   # the scene as it is (no solver given: soft_step)


def test_worker_stops_on_cancel_and_refusals_are_messages():
    proc = _worker()
    _send(proc)
    assert "progress" in _first_progress(proc)
    proc.stdin.write("cancel\n")
    proc.stdin.flush()
    recs = _records(proc)
    assert recs[-1] == {"cancelled": True} and proc.returncode == 0
    assert len(recs) < 10        # stopped at the next run, not after the whole reference and round one
    proc = _worker()
    _send(proc, metric="constraint", scene={**small_scene(), "springs": []})
    last = _records(proc)[-1]
    assert "constraint" in last["error"] and proc.returncode == 0


def test_closing_stdin_cancels_the_worker():
    """The sandbox quit or died: the search stops rather than running on unseen."""
    proc = _worker()
    _send(proc)
    assert "progress" in _first_progress(proc)
    out, _ = proc.communicate(timeout=120)
    assert json.loads(out.splitlines()[-1]) == {"cancelled": True}


def test_cancel_on_a_dask_local_cluster_stops_the_sweep():
    """On Dask the check runs as each result arrives; the futures not yet done are cancelled."""
    done = []
    kw = {**KW, "scheduler": None}           # a LocalCluster (2 worker processes here)
    with pytest.raises(Cancelled):
        physics.tune(small_scene(), cancel=lambda: len(done) >= 3,
                     on_progress=lambda stage, k, n: done.append((stage, k, n)) if k else None, **kw)
    # the reference pair and one run of round one arrived; the check then stopped the search
    assert [s for s, _, _ in done] == ["reference", "reference", "round 1"]
    assert done[-1][1] < done[-1][2]
