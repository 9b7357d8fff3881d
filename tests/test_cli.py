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
