"""The first launch: the gate's compile units (app/compile_units.py) cover the scene's step.

The sandbox compiles the open scene's units on two cores and then plays, with physics'
``compile_on_demand`` off: a world whose one-call step driver is not compiled steps through the
pipeline's stages, which the gate compiled, and a kernel that no unit compiles would be compiled
in the window's process by one core while the other idles.  The driver comes after the gate
(``step:<solver>:<integrator>:<broadphase>[:full][:joints]``, the helper's first background unit)
and the world steps through it from the step after it is loaded.  And the default scene compiles
only the narrow phase's lean kernel.  Run in a fresh process with an empty cache directory (a
cold launch), the default scene, about a minute.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

_SCRIPT = r"""
import json, sys
import physics
from app import compile_units
from app.compile_worker import listen
from physics.step.one_call import compile_on_demand
w = physics.load_scene(sys.argv[1])
key = (w.solver, w.integrator, compile_units.broadphase_of(w))
mine, theirs = compile_units.gate_units(*key)
final = "step:" + ":".join(key) + (":joints" if w.joints else "")
compiled = {u: [] for u in mine + theirs + ["play", final, "driver"]}
now = [None]
listen(lambda k: None, lambda k: compiled[now[0]].append(k))
for u in mine + theirs:
    now[0] = u
    compile_units.run(u)
compile_on_demand(False)          # as the sandbox runs
now[0] = "play"
for _ in range(3):
    w.step()
played = w._pipeline.one_call.P is not None
now[0] = final
compile_units.run(final)
now[0] = "driver"
for _ in range(3):
    w.step()
print("@@" + json.dumps({"units": mine + theirs, "final": final, "compiled": compiled, "played_driver": played,
                         "driver": w._pipeline.one_call.P is not None}))
"""


@pytest.mark.slow
def test_the_scene_plays_on_the_gate_units_and_takes_the_driver_after(tmp_path):
    env = dict(os.environ, STELKROPP_CACHE_DIR=str(tmp_path / "cache"))
    env.pop("NUMBA_CACHE_DIR", None)
    out = subprocess.run([sys.executable, "-c", _SCRIPT, str(ROOT / "scenes" / "default.json")], cwd=ROOT, env=env,
                         capture_output=True, text=True, timeout=900)
    assert out.returncode == 0, out.stderr[-3000:]
    res = json.loads(next(ln[2:] for ln in out.stdout.splitlines() if ln.startswith("@@")))
    compiled = res["compiled"]
    # every gate unit compiled something of its own (a cold cache); the scene then plays on them
    # alone, through the pipeline's stages, compiling nothing
    assert all(compiled[u] for u in res["units"]), {u: len(k) for u, k in compiled.items()}
    assert compiled["play"] == [] and not res["played_driver"], compiled["play"]
    # the driver's unit compiles the one-call step; the world takes it at its next step
    assert "physics.step.soft_driver.soft_world_step" in compiled[res["final"]]
    assert compiled["driver"] == [] and res["driver"], compiled["driver"]
    assert {"physics.step.frame.begin_step", "physics.step.frame.end_step"} <= set(compiled["guard"])
    # the default scene (SAT; boxes, polygons, circles) gets the lean narrow kernel: compiled
    # without GJK, EPA, the rounded and the chain pairs (physics/collision/narrowphase/kernel.py)
    assert "narrow" in res["units"]
    everything = [k for ks in compiled.values() for k in ks]
    assert "physics.collision.narrowphase.kernel._rows" in compiled["narrow"]
    left_out = ("physics.collision.narrowphase.epa.", "physics.collision.narrowphase.gjk.",
                "physics.collision.narrowphase.rounded.round_pair", "physics.collision.narrowphase.chain.")
    assert not [k for k in everything if k.startswith(left_out)]
