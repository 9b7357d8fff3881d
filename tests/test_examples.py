"""Every script in examples/ runs as a user runs it (a subprocess from a fresh folder) and
prints or writes what its docstring promises, checked against analytic answers where there
are some. The pyglet example opens a real window under Xvfb for a few frames.
"""
from __future__ import annotations

import csv
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from bench.xvfb import start_xvfb

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
# a cold numba cache compiles the kernels in the example's own process
TIMEOUT = 1200


def run(script: str, *args, cwd: Path, env=None) -> str:
    proc = subprocess.run([sys.executable, str(EXAMPLES / script), *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=TIMEOUT,
                          env={**os.environ, "PYTHONPATH": str(ROOT), **(env or {})})
    assert proc.returncode == 0, f"{script} exited {proc.returncode}:\n{proc.stdout}\n{proc.stderr[-3000:]}"
    return proc.stdout


def number(text: str, label: str) -> float:
    m = re.search(rf"^{re.escape(label)}\s+([-\d.eE+]+)", text, flags=re.M)
    assert m, f"no {label!r} in:\n{text}"
    return float(m.group(1))


def test_every_example_has_a_docstring_and_a_test():
    import ast
    scripts = sorted(p.name for p in EXAMPLES.glob("*.py"))
    tested = set(re.findall(r'"(\w+\.py)"', Path(__file__).read_text()))
    assert scripts and set(scripts) <= tested, f"examples without a test: {set(scripts) - tested}"
    for name in scripts:
        assert ast.get_docstring(ast.parse((EXAMPLES / name).read_text())), f"{name} has no docstring"


@pytest.mark.parametrize("solver", ["soft_step", "sequential_impulse"])
def test_oscillator_period_matches_analytic(solver, tmp_path):
    """T = 2 pi sqrt(m/k) for m = 1 kg, k = 40 N/m. Bound 0.5 %: bench/accuracy.py's spring
    scenario measures 0.005 % (soft_step) and 0.1 % (sequential_impulse) at dt = 1/60; the
    rest is the interpolation of the turning points between steps."""
    out = run("oscillator_period.py", "--solver", solver, "--plot", tmp_path / "p.png", cwd=tmp_path)
    analytic = 2 * math.pi * math.sqrt(1.0 / 40.0)
    assert number(out, "analytic period:") == pytest.approx(analytic, rel=1e-4)
    measured = number(out, "measured period:")
    assert abs(measured - analytic) / analytic < 0.005, out
    from PIL import Image
    px = np.asarray(Image.open(tmp_path / "p.png").convert("RGB")).astype(int)
    blue = (abs(px[..., 0] - 0x1F) < 30) & (abs(px[..., 1] - 0x77) < 30) & (abs(px[..., 2] - 0xB4) < 30)
    # the simulated curve (matplotlib's first colour, under the dashed analytic one) spans the axes
    assert blue.any(axis=0).sum() > 500, "the plot has no simulated curve across its width"


def test_export_trajectory_csv_equals_npz_and_physics(tmp_path):
    out = run("export_trajectory.py", "--steps", 180, "--out", tmp_path / "out", cwd=tmp_path)
    assert "wrote" in out
    data = np.load(tmp_path / "out" / "trajectory.npz")
    t, S = data["time"], data["state"]
    assert S.shape == (181, 3) and S.dtype.names == ("id", "position", "angle", "velocity",
                                                     "angular_velocity", "awake")
    with open(tmp_path / "out" / "trajectory.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 181 * 3
    for row in rows[::7]:  # the CSV holds the same numbers, exactly
        k, body = int(row["step"]), (int(row["id"]) - 1)
        assert float(row["time"]) == t[k]
        assert (float(row["x"]), float(row["y"])) == tuple(S[k, body]["position"])
        assert float(row["vy"]) == S[k, body]["velocity"][1]
    # the ball falls freely from 2.25 m until it touches the ground at 0.25 m (t = 0.639 s):
    # y = y0 - g t^2 / 2 within the first-order error of a step, g dt t
    g, dt = 9.81, 1 / 60
    y = S[:, 1]["position"][:, 1]
    free = t < 0.6
    assert np.all(np.abs(y[free] - (2.25 - g * t[free] ** 2 / 2)) <= g * dt * t[free] + 1e-12)
    # restitution 0.5 from a 2 m drop: the first bounce rises e^2 h = 0.5 m (bench accuracy,
    # `bounce`: soft_step 0.469 m); the apex is the highest point after the ball first rises
    rising = np.nonzero(S[:, 1]["velocity"][:, 1] > 0)[0][0]
    apex = y[rising:].max() - 0.25
    assert 0.40 < apex < 0.55, apex
    assert S[-1, 2]["position"][0] > -3.0  # the thrown box travelled right


def test_build_scene_writes_a_valid_file_and_reports_broken_fields(tmp_path):
    out = run("build_scene.py", "--out", tmp_path / "stairs.json", cwd=tmp_path)
    assert "schema: valid" in out
    assert "loaded: 13 bodies, 1 springs" in out
    assert "ok (13 bodies, 1 springs) (exit 0)" in out
    assert "broken: 3 problems" in out
    for path in ("bodies[1].shape.polygon: polygon is not convex", "bodies[7].restitution: must be <= 1",
                 "springs[0].a: no body named 'crane'"):
        assert path in out, out
    import physics
    world = physics.load_scene(tmp_path / "stairs.json")
    assert world.body("ball4").restitution == 0.95 and world.spring("hook").stiffness == 120


def test_compare_solvers_both_modes_hold_the_pyramid(tmp_path):
    """docs/reliability.md, 'far from origin': the same 55-box pyramid drifts 3.3 mm
    (soft_step) and 4.6 mm (sequential_impulse) in 5 s; bound 2 cm."""
    out = run("compare_solvers.py", "--modes", "soft_step,sequential_impulse", "--steps", 300, cwd=tmp_path)
    rows = {m.group(1): (float(m.group(2)), float(m.group(3)), float(m.group(4)))
            for m in re.finditer(r"^(\w+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)$", out, flags=re.M)}
    assert set(rows) == {"soft_step", "sequential_impulse"}, out
    assert rows["soft_step"][1] == 1.0
    for mode, (ms, ratio, drift) in rows.items():
        assert ms > 0 and ratio > 0, out
        assert drift < 0.02, f"{mode}: top box drifted {drift} m"


# -- the pyglet window under Xvfb ------------------------------------------------------------
def _xvfb(tmp_path):
    if shutil.which("Xvfb") is None:
        pytest.fail("the pyglet example needs Xvfb: apt-get install -y xvfb (.ci/run installs it)", pytrace=False)
    try:
        return start_xvfb()
    except RuntimeError as exc:
        pytest.fail(str(exc), pytrace=False)


@pytest.mark.app
def test_pyglet_window_draws_the_scene(tmp_path):
    proc, display = _xvfb(tmp_path)
    try:
        shot = tmp_path / "frame.png"
        out = run("pyglet_window.py", ROOT / "scenes" / "pyramid.json", "--frames", 30, "--screenshot", shot,
                  cwd=tmp_path, env={"DISPLAY": display})
    finally:
        proc.terminate()
        proc.wait(10)
    assert "drew 30 frames of 211 bodies" in out, out
    from PIL import Image
    px = np.asarray(Image.open(shot).convert("RGB")).astype(int)
    assert px.shape == (600, 960, 3)
    orange = (px[..., 0] > 200) & (px[..., 1] > 130) & (px[..., 1] < 220) & (px[..., 2] < 140)
    grey = (abs(px[..., 0] - 110) < 30) & (abs(px[..., 2] - 140) < 30) & (abs(px[..., 1] - 120) < 30)
    # 210 unit boxes at the scene camera's zoom cover thousands of pixels; the ground is a grey bar
    assert orange.sum() > 5000, f"dynamic bodies not drawn ({orange.sum()} orange pixels)"
    assert grey.sum() > 2000, f"static ground not drawn ({grey.sum()} grey pixels)"
    ys, xs = np.nonzero(orange)
    assert ys.mean() < np.nonzero(grey)[0].mean(), "the pyramid should stand above the ground"
