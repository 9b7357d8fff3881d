"""The tuner (issue 19): python -m physics tune / physics.tune.

Scenes are tiny (2-3 bodies, 48-480 steps) and the searches limited to one or two modes so the
file stays well under a minute here; the Dask test starts a real LocalCluster (2 worker processes).
"""
import json

import pytest

import physics
from physics import cli
from physics.tuning import candidates as grid
from physics.tuning import metrics, runs, search, sweep


@pytest.fixture
def counted(monkeypatch):
    """The keys of the runs the tuner really ran, in order."""
    from physics.tuning import search
    calls = []
    real = search.task

    def counting(cand, *args):
        calls.append(cand.key)
        return real(cand, *args)
    monkeypatch.setattr(search, "task", counting)
    return calls


def small_scene():
    """A box sliding on the ground and a bob on a spring: contacts, friction and a spring."""
    return {"format": "stelkropp.scene", "version": 1, "name": "small", "description": "kept by --apply",
            "world": {"gravity": [0, -10]},
            "bodies": [{"name": "ground", "kind": "static", "shape": {"box": [10, 1]}, "position": [0, -0.5]},
                       {"name": "box", "shape": {"box": [1, 1]}, "position": [0, 0.5], "velocity": [1, 0]},
                       {"name": "bob", "shape": {"circle": 0.2}, "position": [3, 2]}],
            "springs": [{"a": "bob", "b": None, "anchor_b": [3, 3], "stiffness": 200, "rest_length": 0.5}]}


def double_pendulum():
    """Two bobs on stiff springs (rods), released near the top: chaotic within a few seconds."""
    return {"format": "stelkropp.scene", "version": 1, "world": {"gravity": [0, -10]},
            "bodies": [{"name": "a", "shape": {"circle": 0.1}, "position": [0.3, 0.954]},
                       {"name": "b", "shape": {"circle": 0.1}, "position": [1.2, 1.4]}],
            "springs": [{"a": "a", "b": None, "anchor_b": [0, 0], "stiffness": 1e5},
                        {"a": "a", "b": "b", "stiffness": 1e5}]}


def test_choice_is_within_budget_when_re_measured_against_the_reference():
    budget = 0.01
    modes = ["soft_step", "sequential_impulse"]
    res = physics.tune(small_scene(), steps=48, budget=budget, scheduler="inline", modes=modes, progress=False)
    # the 48-step reference and one twice as fine differ by ~1.3 mm here: well under half the budget
    assert res.converged and res.reference_gap < 0.5 * budget and "converged" in res.note
    assert res.choice is not None
    # re-run the chosen settings and the reference independently and measure again
    data = small_scene()
    stride = 8
    ref = runs.run_case(data, grid.REFERENCE, res.steps, stride)
    again = runs.run_case(data, res.choice["candidate"], res.steps, stride)
    err = metrics.compare(again, ref, "trajectory")["error"]
    assert err <= budget and err == pytest.approx(res.choice["error"], rel=1e-9, abs=1e-15)
    # the choice is the fastest of the candidates within the budget, up to timing noise: among
    # those timed within search.TIE of the fastest, the one with the least solver work; and it
    # is on the Pareto front
    within = [r for r in res.rows if r["within"] and r["candidate"].solver in modes]
    fastest = min(r["seconds"] for r in within)
    ties = [r for r in within if r["seconds"] <= fastest * (1.0 + search.TIE)]
    assert res.choice in ties
    assert search.work(res.choice["candidate"]) == min(search.work(r["candidate"]) for r in ties)
    assert res.choice in res.front
    # the fragment applies it: building the scene with it gives the chosen run bit for bit
    frag = res.fragment
    applied = runs.run_case({**data, "world": {**data["world"], **frag}}, runs.Candidate(frag["solver"]),
                            round(res.steps / res.choice["candidate"].dt_factor), round(stride / res.choice["candidate"].dt_factor))
    assert (applied.positions[-1] == again.positions[-1]).all()


def test_chaotic_scene_falls_back_to_statistical_measures_and_says_so():
    res = physics.tune(double_pendulum(), steps=480, budget=0.01, scheduler="inline", modes=["soft_step"],
                       progress=False)
    # the two reference runs end ~13 cm apart (measured here), far beyond half the 1 cm budget
    assert not res.converged and res.reference_gap > 0.005
    assert "chaotic" in res.note and "statistical" in res.note
    assert all(set(r["measures"]) >= {"gain", "rest", "depth"} for r in res.rows)


def test_cli_apply_writes_the_choice_and_keeps_the_rest(tmp_path, capsys):
    path = tmp_path / "small.json"
    path.write_text(json.dumps(small_scene(), indent=1))
    code = cli.main(["tune", str(path), "--steps", "48", "--budget", "0.5", "--scheduler", "inline",
                     "--modes", "sequential_impulse", "--apply", "--json", str(tmp_path / "rows.json")])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert "<- chosen" in out and "applied to" in out
    rows = json.loads((tmp_path / "rows.json").read_text())
    chosen = next(r for r in rows["rows"] if r["key"] == rows["choice"])
    # sequential_impulse is ~0.22 m off the soft_step reference on this scene (measured here)
    assert chosen["within"] and chosen["error"] <= 0.5
    data = json.loads(path.read_text())
    before = small_scene()
    assert data["world"]["solver"] == "sequential_impulse"
    assert {k: data[k] for k in ("name", "description", "bodies", "springs")} == \
        {k: before[k] for k in ("name", "description", "bodies", "springs")}
    assert data["world"]["gravity"] == [0, -10]
    w = physics.load_scene(path)  # the applied file loads and carries the chosen settings
    assert w.solver == "sequential_impulse"
    assert all(w.settings[k] == v for k, v in data["world"]["settings"].items())
    assert chosen["key"].startswith("sequential_impulse")
    assert w.dt == data["world"]["dt"]


@pytest.mark.parametrize("args, words", [
    (["--budget", "-1"], "budget: must be a positive finite number"),
    (["--budget", "nan"], "budget: must be a positive finite number"),
    (["--budget", "lots"], "budget: must be a positive finite number"),
    (["--budget", "0.01", "--metric", "speed"], "metric: unknown metric 'speed'"),
    (["--budget", "0.01", "--modes", "xpbd"], "modes: unknown solver mode"),
    (["--budget", "0.01", "--steps", "3"], "steps: must be a whole number >= 8"),
])
def test_bad_options_are_clear_errors_and_the_file_is_untouched(tmp_path, capsys, args, words):
    path = tmp_path / "s.json"
    text = json.dumps(small_scene())
    path.write_text(text)
    code = cli.main(["tune", str(path), "--scheduler", "inline", "--apply", *args])
    err = capsys.readouterr().err
    assert code == 1 and words in err and "Traceback" not in err
    assert path.read_text() == text


def test_broken_scene_and_unreachable_scheduler(tmp_path, capsys, monkeypatch):
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "stelkropp.scene", "version": 1, "bodies": [{"shape": {"circle": -1}}]}')
    assert cli.main(["tune", str(bad), "--budget", "0.01", "--scheduler", "inline"]) == 1
    assert "bodies[0]" in capsys.readouterr().err
    monkeypatch.setattr(sweep, "CONNECT_SECONDS", 2)
    good = tmp_path / "good.json"
    good.write_text(json.dumps(small_scene()))
    assert cli.main(["tune", str(good), "--budget", "0.01", "--scheduler", "tcp://127.0.0.1:9"]) == 1
    assert "scheduler: cannot reach tcp://127.0.0.1:9" in capsys.readouterr().err


def test_sweep_on_a_dask_local_cluster_matches_the_inline_run():
    kw = dict(steps=16, budget=0.05, modes=["soft_step"], progress=False)
    local = physics.tune(small_scene(), scheduler=None, **kw)  # LocalCluster, 2 processes
    inline = physics.tune(small_scene(), scheduler="inline", **kw)
    assert "LocalCluster" in local.where
    # deterministic physics: a candidate's error is the same bit for bit wherever it ran (round two
    # refines the speed/error front, which depends on timings, so only shared keys are compared;
    # round one's are always shared)
    a, b = ({r["key"]: r["error"] for r in res.rows} for res in (local, inline))
    shared = a.keys() & b.keys()
    assert len(shared) > len(grid.round_one(["soft_step"]))
    assert {k: a[k] for k in shared} == {k: b[k] for k in shared}
    assert local.choice["within"] and inline.choice["within"]  # which is fastest is a timing: may differ


def test_results_stream_to_a_file_and_resume_runs_only_the_missing_cases(tmp_path, counted):
    calls = counted
    kw = dict(steps=16, budget=0.05, modes=["soft_step"], scheduler="inline", progress=False)
    results = tmp_path / "runs.jsonl"
    first = physics.tune(small_scene(), results=results, **kw)
    lines = results.read_text().splitlines()
    assert len(lines) == 1 + len(calls) == 1 + 2 + len(first.rows)  # header, reference pair, every row
    # an interrupted sweep: the file ends after 10 runs, the last line cut in half by the kill
    results.write_text("\n".join(lines[:11]) + "\n" + lines[11][:40])
    calls.clear()
    again = physics.tune(small_scene(), results=results, resume=True, **kw)
    assert len(calls) == len(lines) - 11  # only the missing ones ran (the cut one again)
    assert not set(calls) & {json.loads(x)["key"] for x in lines[1:11]}
    # the stored runs stand for new ones: the same errors, bit for bit
    assert {r["key"]: r["error"] for r in again.rows} == {r["key"]: r["error"] for r in first.rows}
    # a results file of another scene (or step count) is refused, not mixed in
    with pytest.raises(ValueError, match="^results: .* another scene"):
        physics.tune(double_pendulum(), results=results, resume=True, **kw)

