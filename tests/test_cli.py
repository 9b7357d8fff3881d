"""The headless command line: simulate / validate / info (in-process through main(argv), plus
one real subprocess for ``python -m physics``)."""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import physics
from physics import cli

ROOT = Path(__file__).resolve().parent.parent
SCENE = str(ROOT / "scenes" / "restitution_row.json")
BAD = {"format": "stelkropp.scene", "version": 1,
       "bodies": [{"name": "x", "shape": {"box": [1, -1]}, "position": [0, 0], "density": -2}]}


def run(capsys, *argv):
    code = cli.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture
def bad_scene(tmp_path):
    p = tmp_path / "bad.json"
    p.write_text(json.dumps(BAD))
    return p


def test_simulate_writes_the_final_state(capsys):
    code, out, err = run(capsys, "simulate", SCENE, "--steps", 30)
    assert code == 0
    res = json.loads(out)
    assert res["steps"] == 30 and res["time"] == pytest.approx(0.5) and res["finite"] is True
    names = [b["name"] for b in res["bodies"]]
    assert names[0] == "ground" and "ball_e0.5" in names
    ball = res["bodies"][names.index("ball_e0.5")]
    assert set(ball) == {"name", "position", "angle", "velocity", "angular_velocity"}
    assert ball["position"][1] < 6.0 and ball["velocity"][1] < 0  # falling
    assert "frames" not in res
    assert err == ""  # no progress bar when stderr is not a terminal


def test_simulate_matches_the_library(capsys):
    code, out, _ = run(capsys, "simulate", SCENE, "--steps", 20)
    w = physics.load_scene(SCENE)
    for _ in range(20):
        w.step()
    assert json.loads(out)["bodies"] == json.loads(json.dumps(cli.state(w)))["bodies"]


def test_simulate_options_and_out_file(capsys, tmp_path):
    out_file = tmp_path / "state.json"
    code, out, _ = run(capsys, "simulate", SCENE, "--steps", 10, "--solver", "sequential_impulse", "--dt", 0.01,
                       "--set", "gravity=[0,-1]", "--set", "sleeping=false", "--out", out_file, "--record", 5)
    assert code == 0 and out == ""
    res = json.loads(out_file.read_text())
    assert res["time"] == pytest.approx(0.1)
    assert [f["steps"] for f in res["frames"]] == [0, 5, 10]
    ball = next(b for b in res["bodies"] if b["name"] == "ball_e0.0")
    assert ball["velocity"][1] == pytest.approx(-0.1, abs=1e-6)  # gravity -1 for 0.1 s


def test_simulate_sets_solver_settings(capsys, monkeypatch):
    seen = {}
    real = physics.World.step

    def spy(self, dt=None):
        seen.update(self.settings.to_dict())
        return real(self, dt)

    monkeypatch.setattr(physics.World, "step", spy)
    code, _, _ = run(capsys, "simulate", SCENE, "--steps", 1, "--set", "substeps=8", "--set", "relax=false")
    assert code == 0 and seen["substeps"] == 8 and seen["relax"] is False


@pytest.mark.parametrize("args, words", [
    (["--set", "warp=9"], "has no setting 'warp'"),
    (["--set", "substeps=0"], ">= 1"),
    (["--set", "substeps"], "KEY=VALUE"),
    (["--set", "gravity=[NaN,0]"], "not finite"),
    (["--solver", "magic"], "unknown solver"),
    (["--dt", "-1"], "dt"),
])
def test_simulate_bad_options_exit_1(capsys, args, words):
    code, out, err = run(capsys, "simulate", SCENE, "--steps", 1, *args)
    assert code == 1 and out == ""
    assert words in err


def test_simulation_error_gives_finite_false_and_exit_2(capsys, monkeypatch):
    real = physics.World.step

    def blow_up(self, dt=None):
        if self.steps == 3:
            raise physics.SimulationError("step at t=0.05 s produced non-finite values", bodies=["x"])
        return real(self, dt)

    monkeypatch.setattr(physics.World, "step", blow_up)
    code, out, err = run(capsys, "simulate", SCENE, "--steps", 10)
    assert code == 2
    res = json.loads(out)
    assert res["finite"] is False and res["steps"] == 3
    assert "non-finite" in res["error"] and "non-finite" in err


def test_simulate_bad_scene_exits_1(capsys, bad_scene):
    code, out, err = run(capsys, "simulate", bad_scene, "--steps", 1)
    assert code == 1 and out == ""
    assert "bodies[0].shape.box[1]" in err and "bodies[0].density" in err


def test_validate(capsys, bad_scene):
    good = ROOT / "scenes" / "pyramid.json"
    code, out, _ = run(capsys, "validate", good, SCENE)
    assert code == 0 and out.count(": ok (") == 2
    code, out, _ = run(capsys, "validate", good, bad_scene)
    assert code == 1
    assert f"{bad_scene}: 2 problems in scene" in out
    assert "bodies[0].shape.box[1]: must be > 0" in out and "bodies[0].density: must be > 0" in out


def test_info(capsys):
    code, out, _ = run(capsys, "info", ROOT / "scenes" / "spring_playground.json")
    assert code == 0
    assert "Spring playground" in out and "springs:    6" in out and "soft_step" in out
    assert "stages:" in out and "substeps=" in out
    code, out, _ = run(capsys, "info", "--json", SCENE)
    data = json.loads(out)
    assert data["bodies"] == 6 and data["springs"] == 0 and data["solver"] == "soft_step"
    assert data["stages"] == physics.load_scene(SCENE).info()["stages"]
    assert not any("spring" in s for s in data["stages"])


def test_progress_bar_only_on_a_terminal(monkeypatch, capsys):
    made = []
    import tqdm as tqdm_mod
    real = tqdm_mod.tqdm

    def spy(*a, **k):
        made.append(k.get("disable"))
        return real(*a, **k)

    monkeypatch.setattr(tqdm_mod, "tqdm", spy)
    run(capsys, "simulate", SCENE, "--steps", 1)
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True, raising=False)
    run(capsys, "simulate", SCENE, "--steps", 1)
    assert made == [True, False]


def test_python_dash_m_physics(tmp_path, bad_scene):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    ok = subprocess.run([sys.executable, "-m", "physics", "validate", SCENE], capture_output=True, text=True,
                        env=env, cwd=tmp_path, timeout=600)
    assert ok.returncode == 0, ok.stderr
    bad = subprocess.run([sys.executable, "-m", "physics", "validate", str(bad_scene)], capture_output=True,
                         text=True, env=env, cwd=tmp_path, timeout=600)
    assert bad.returncode == 1 and "bodies[0].density" in bad.stdout


def test_console_script_is_declared():
    text = (ROOT / "pyproject.toml").read_text()
    assert 'stelkropp-sim = "physics.cli:main"' in text


def test_schema_prints_the_published_schema(capsys):
    code, out, _ = run(capsys, "schema")
    assert code == 0 and out == (ROOT / "scenes" / "stelkropp.schema.json").read_text()


# -- issue 20: hostile input never gives a traceback ----------------------------------------------
def scene_file(tmp_path, text, name="hostile.json"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8", errors="surrogatepass")
    return p


def lone_surrogate_scene(tmp_path):
    data = json.loads(Path(SCENE).read_text())
    data["name"] = "evil@name"
    return scene_file(tmp_path, json.dumps(data).replace("@", "\\ud800"))


def test_info_and_validate_refuse_a_name_with_a_lone_surrogate(capsys, tmp_path):
    p = lone_surrogate_scene(tmp_path)
    code, out, err = run(capsys, "info", p)
    assert code == 1 and out == "" and "lone surrogate" in err and "Traceback" not in err
    code, out, _ = run(capsys, "validate", p)
    assert code == 1 and ": ok (" not in out and "name: not valid Unicode" in out


def test_python_dash_m_physics_with_hostile_scenes_prints_no_traceback(tmp_path):
    """Real processes (their stdout/stderr encodings, not pytest's): each hostile scene exits 1."""
    env = dict(os.environ, PYTHONPATH=str(ROOT), PYTHONIOENCODING="utf-8")
    deep = scene_file(tmp_path, '{"format": "stelkropp.scene", "version": 1, "bodies": ' + "[" * 500 + "]" * 500 + "}",
                      "deep.json")
    big = scene_file(tmp_path, Path(SCENE).read_text().replace('"restitution": 0.5', '"restitution": ' + "9" * 400),
                     "big.json")
    weird_name = tmp_path / os.fsdecode(b"caf\xe9.json")  # not UTF-8: argv carries a lone surrogate
    weird_name.write_text(Path(SCENE).read_text())
    for args, code in ((["info", lone_surrogate_scene(tmp_path)], 1), (["validate", deep, big], 1),
                       (["info", weird_name], 0), (["validate", weird_name], 0)):
        res = subprocess.run([sys.executable, "-m", "physics", *map(str, args)], capture_output=True, text=True,
                             env=env, cwd=tmp_path, timeout=600, errors="backslashreplace")
        assert res.returncode == code, (args, res.stdout, res.stderr)
        assert "Traceback" not in res.stderr, res.stderr


@pytest.mark.parametrize("where, words", [
    ("folder", "is a folder"),
    ("missing/state.json", "does not exist"),
    ("n" * 300 + ".json", "file name is longer"),
])
def test_bad_out_is_refused_before_the_run(capsys, tmp_path, monkeypatch, where, words):
    ran = []
    monkeypatch.setattr(physics.World, "step", lambda self, dt=None: ran.append(1))
    (tmp_path / "folder").mkdir()
    code, out, err = run(capsys, "simulate", SCENE, "--steps", 5, "--out", tmp_path / where)
    assert code == 1 and out == "" and words in err and not ran


def test_out_that_fails_after_the_run_still_gives_the_result(capsys, tmp_path, monkeypatch):
    import physics.scene.atomic as atomic

    def full(*_):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(atomic.os, "fsync", full)
    code, out, err = run(capsys, "simulate", SCENE, "--steps", 3, "--out", tmp_path / "state.json")
    assert code == 1 and "No space left" in err and json.loads(out)["steps"] == 3
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("value, words", [
    ("substeps=" + "9" * 400, "not finite"),
    ("substeps=" + "9" * 5000, "not finite"),
    ("gravity=[0," + "9" * 400 + "]", "not finite"),
    ("gravity=" + "[" * 100_000, "gravity"),
    ("integrator=" + "x" * 2_000_000, "integrator"),
    ("relax=" + "[" * 50 + "]" * 50, "relax"),
])
def test_huge_set_values_exit_1_with_a_short_message(capsys, value, words):
    code, out, err = run(capsys, "simulate", SCENE, "--steps", 1, "--set", value)
    assert code == 1 and out == "" and words in err
    assert len(err) < 2000


@pytest.mark.parametrize("steps", ["-1", "1e3", "9" * 5000])
def test_bad_step_counts_exit_1(capsys, steps):
    with pytest.raises(SystemExit) as info:
        cli.main(["simulate", SCENE, "--steps", steps])
    assert info.value.code == 1
    assert len(capsys.readouterr().err) < 2000


def test_non_finite_state_is_written_as_null_not_a_traceback(capsys, monkeypatch):
    real = cli.state

    def overflowed(world):
        st = real(world)
        st["bodies"][1]["velocity"] = [float("inf"), 0.0]
        return st

    monkeypatch.setattr(cli, "state", overflowed)
    code, out, err = run(capsys, "simulate", SCENE, "--steps", 2)
    res = json.loads(out)
    assert code == 2 and res["finite"] is False and res["bodies"][1]["velocity"] == [None, 0.0]
    assert "non-finite" in res["error"] and "non-finite" in err


@pytest.mark.parametrize("word, on", [("off", False), ("OFF", False), ("no", False), ("0", False), ("false", False),
                                      ("on", True), ("Yes", True), ("1", True), ("true", True)])
def test_set_sleeping_accepts_on_off_words(capsys, monkeypatch, word, on):
    """Issue 20 item 5: ``--set sleeping=off`` turned sleeping on (a non-empty string is truthy)."""
    seen = {}
    real = physics.World.step

    def spy(self, dt=None):
        seen["sleeping"], seen["relax"] = self.sleeping, self.settings["relax"]
        return real(self, dt)

    monkeypatch.setattr(physics.World, "step", spy)
    code, _, err = run(capsys, "simulate", SCENE, "--steps", 1, "--solver", "soft_step",
                       "--set", f"sleeping={word}", "--set", f"relax={word}")
    assert code == 0, err
    assert seen == {"sleeping": on, "relax": on}


@pytest.mark.parametrize("item", ["sleeping=maybe", "sleeping=2", "sleeping=", "relax=offf", "relax=[1]"])
def test_set_switch_with_another_word_exits_1_naming_it(capsys, item):
    code, out, err = run(capsys, "simulate", SCENE, "--steps", 1, "--solver", "soft_step", "--set", item)
    key = item.partition("=")[0]
    assert code == 1 and out == ""
    assert f"--set {key}: expected one of true, on, yes, 1, false, off, no, 0" in err
