"""bench and bench.reliability on a real Dask cluster started by the test on localhost (issue 19):
a ``dask scheduler`` and two one-thread ``dask worker`` processes (tests/dask_procs.py).

The figures (not the timings) must equal the run in this process bit for bit: the physics is
deterministic and a case carries its scene as data.  Small sweeps: the quick accuracy cases of
one mode, two cheap reliability probes in two modes."""
import json
import math

from dask_procs import dask_cluster

# bench.cli (and the engines it imports) at import time, not under capsys: an import under it
# left sys.stdout on capsys's closed buffer for the later tests (tests/test_bench_smoke.py)
from bench import cli
from bench.accuracy_runs import accuracy_runs
from bench.reliability import cli as rel
from bench.reliability.probes import PROBES
from bench.sweep import Sweep

PROBE_NAMES = ("stiff_spring", "coincident")
MODES = ["soft_step", "sequential_impulse"]


def _probes():
    return [p for p in PROBES if p.measure.__name__ in PROBE_NAMES]


def _figures(table) -> dict:
    """Every outcome without its wall time, NaN made comparable."""
    return json.loads(json.dumps({(f"{n} {m}"): [o.status, o.figure, o.metrics] for n, per in table.items()
                                  for m, o in per.items()}, default=str).replace("NaN", '"nan"'))


def _rows(rows) -> list:
    return json.loads(json.dumps(rows, default=str).replace("NaN", '"nan"'))


def test_bench_accuracy_and_reliability_through_a_scheduler_equal_the_local_run(tmp_path):
    with dask_cluster(tmp_path) as (address, _):
        with Sweep(address, progress=False) as sw:
            remote_acc = accuracy_runs(["soft_step"], quick=True, sweep=sw)
        remote_rel = rel.run_probes(_probes(), MODES, quick=True, scheduler=address)
    with Sweep("inline", progress=False) as sw:
        local_acc = accuracy_runs(["soft_step"], quick=True, sweep=sw)
    local_rel = rel.run_probes(_probes(), MODES, quick=True, scheduler="inline")
    assert len(remote_acc) > 5 and _rows(remote_acc) == _rows(local_acc)
    assert len(_figures(remote_rel)) == 4 and _figures(remote_rel) == _figures(local_rel)


def test_reliability_results_stream_and_resume_runs_only_the_missing(tmp_path, monkeypatch, capsys):
    from bench.reliability import probes as pr
    calls = []
    real = pr.run_probe

    def counting(probe, mode, **kw):
        calls.append((probe.measure.__name__, mode))
        return real(probe, mode, **kw)
    monkeypatch.setattr(pr, "run_probe", counting)
    path = tmp_path / "rel.jsonl"
    first = rel.run_probes(_probes(), MODES, quick=True, scheduler="inline", results=path)
    lines = path.read_text().splitlines()
    assert len(lines) == 1 + 4 == 1 + len(calls)  # the header, then every probe x mode as it finished
    path.write_text("\n".join(lines[:3]) + "\n" + lines[3][:30])  # killed during the third
    calls.clear()
    again = rel.run_probes(_probes(), MODES, quick=True, scheduler="inline", results=path, resume=True)
    assert len(calls) == 2 and _figures(again) == _figures(first)
    assert all(math.isfinite(o.seconds) for per in again.values() for o in per.values())


def test_unreachable_scheduler_is_a_clear_error_and_writes_nothing(tmp_path, monkeypatch, capsys):
    from physics.tuning import sweep
    monkeypatch.setattr(sweep, "CONNECT_SECONDS", 2)
    out = tmp_path / "rel.md"
    code = rel.main(["--probes", "stiff_spring", "--modes", "soft_step", "--scheduler", "tcp://127.0.0.1:9",
                     "--out", str(out)])
    err = capsys.readouterr().err
    assert code == 1 and "scheduler: cannot reach tcp://127.0.0.1:9" in err and "Traceback" not in err
    assert not out.exists()
    bench_out = tmp_path / "bench"
    assert cli.main(["--tiny", "--no-refs", "--parts", "accuracy", "--modes", "soft_step", "--out", str(bench_out),
                     "--scheduler", "tcp://127.0.0.1:9"]) == 1
    assert "scheduler: cannot reach" in capsys.readouterr().err
    assert not (bench_out / "bench.json").exists()
