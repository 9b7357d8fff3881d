"""Issue 16, first launch: the gate's compile units (app/compile_units.py) cover the whole step.

The sandbox compiles the open scene's units on two cores and then takes one last step
(``step:<solver>:<integrator>:<broadphase>``), which should only load what the two processes
put in the cache: a kernel that no unit compiles is compiled there, by one core, while the other
idles (the step's own two kernels were such a tail: 4 CPU s of a 46 s cold launch).  And the
default scene compiles only the narrow phase's lean kernel.  Run in a
fresh process with an empty cache directory (a cold launch), the default scene, about a minute.
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
w = physics.load_scene(sys.argv[1])
key = (w.solver, w.integrator, compile_units.broadphase_of(w))
mine, theirs = compile_units.gate_units(*key)
units = mine + theirs + ["step:" + ":".join(key)]
compiled = {u: [] for u in units}
now = [None]
listen(lambda k: None, lambda k: compiled[now[0]].append(k))
for u in units:
    now[0] = u
    compile_units.run(u)
print("@@" + json.dumps({"units": units, "compiled": compiled}))
"""


@pytest.mark.slow
def test_the_gate_units_leave_the_last_step_nothing_to_compile(tmp_path):
    env = dict(os.environ, STELKROPP_CACHE_DIR=str(tmp_path / "cache"))
    env.pop("NUMBA_CACHE_DIR", None)
    out = subprocess.run([sys.executable, "-c", _SCRIPT, str(ROOT / "scenes" / "default.json")], cwd=ROOT, env=env,
                         capture_output=True, text=True, timeout=900)
    assert out.returncode == 0, out.stderr[-3000:]
    res = json.loads(next(ln[2:] for ln in out.stdout.splitlines() if ln.startswith("@@")))
    compiled = res["compiled"]
    final = res["units"][-1]
    # every gate unit compiled something of its own (a cold cache), the last step nothing
    assert all(compiled[u] for u in res["units"][:-1]), {u: len(k) for u, k in compiled.items()}
    assert compiled[final] == [], compiled[final]
    assert {"physics.step.frame.begin_step", "physics.step.frame.end_step"} <= set(compiled["guard"])
    # the default scene (SAT; boxes, polygons, circles) gets the lean narrow kernel: compiled
    # without GJK, EPA, the rounded and the chain pairs (physics/collision/narrowphase/kernel.py)
    assert "narrow" in res["units"]
    everything = [k for ks in compiled.values() for k in ks]
    assert "physics.collision.narrowphase.kernel._rows" in compiled["narrow"]
    left_out = ("physics.collision.narrowphase.epa.", "physics.collision.narrowphase.gjk.",
                "physics.collision.narrowphase.rounded.round_pair", "physics.collision.narrowphase.chain.")
    assert not [k for k in everything if k.startswith(left_out)]
