"""Determinism: the same scene and settings give bit-identical states (issue 5).

Kernels run serially with fastmath off, contact rows are sorted by stable
keys and pairs come out of the broad phase in a fixed order, so nothing
depends on timing, hashing or thread scheduling: two runs in one process and
a run in a fresh process must agree to the last bit after 1000 steps.
"""
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import physics
from builders import container, state_digest

ROOT = Path(__file__).resolve().parent.parent
STEPS = 1000


def build(solver: str, sleeping: bool = True) -> physics.World:
    w = physics.World(gravity=(0.0, -10.0), dt=1 / 60, solver=solver, sleeping=sleeping)
    container(w, width=15, height=8, floor_width=30)
    rng = np.random.default_rng(7)
    bodies = []
    for i in range(60):
        x = rng.uniform(-6.5, 6.5)
        y = 1.0 + 0.9 * i
        if i % 4 == 3:
            b = w.add_body(physics.Circle(rng.uniform(0.2, 0.45)), position=(x, y), restitution=0.3)
        else:
            b = w.add_body(physics.Polygon.box(rng.uniform(0.3, 1.2), rng.uniform(0.3, 1.0)), position=(x, y),
                           angle=rng.uniform(-1, 1), friction=(0.7, 0.5))
        bodies.append(b)
    w.add_spring(bodies[0], bodies[1], stiffness=200.0, damping=2.0)
    w.add_spring(bodies[5], None, anchor_b=(0.0, 12.0), stiffness=5e4, damping=10.0)
    return w


def run(solver: str, sleeping: bool = True) -> str:
    w = build(solver, sleeping)
    for _ in range(STEPS):
        w.step()
    return state_digest(w)


@pytest.mark.parametrize("solver", ["soft_step", "sequential_impulse"])
def test_two_runs_bit_identical(solver):
    assert run(solver) == run(solver)


def test_sleep_off_runs_bit_identical():
    assert run("soft_step", sleeping=False) == run("soft_step", sleeping=False)


@pytest.mark.parametrize("solver", ["soft_step", "sequential_impulse"])
def test_two_processes_bit_identical(solver):
    here = run(solver)
    code = (f"import sys; sys.path.insert(0, {str(ROOT)!r}); sys.path.insert(0, {str(ROOT / 'tests')!r});"
            f"import test_determinism as t; print(t.run({solver!r}))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=900)
    assert out.returncode == 0, out.stderr[-2000:]
    assert out.stdout.strip().splitlines()[-1] == here
