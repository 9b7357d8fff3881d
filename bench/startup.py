"""Start-up cost: kernel compile on first use and a cached start, each in a new process."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time

from .paths import ROOT

_COMPILE_SCRIPT = r"""
import json, sys, time
t0 = time.perf_counter()
import physics
t_import = time.perf_counter() - t0
out = {"import_s": t_import, "first_step_s": {}}
modes = sys.argv[1].split(",")
for m in modes:
    w = physics.World(solver=m, sleeping=True, gravity=(0, -10))
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    a = w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5))
    w.add_body(physics.Circle(0.3), position=(0.2, 1.4))
    w.add_body(physics.Polygon.regular(6, 0.4), position=(-0.3, 2.3))
    w.add_spring(a, None, anchor_b=(0, 3), stiffness=50, damping=1)
    t = time.perf_counter()
    for _ in range(3):
        w.step()
    out["first_step_s"][m] = time.perf_counter() - t
out["startup_s"] = time.perf_counter() - t0
print("@@" + json.dumps(out))
"""


def source_hash():
    """The hash the numba cache is keyed on (physics/ sources)."""
    from physics._jit import _source_hash
    return _source_hash()


def compile_times(modes, phases=("cold", "cached"), timeout=1500):
    """Kernel compile on first use and a cached start, each timed in a new process: import time,
    the first three steps per mode (a scene with polygons, a circle and a spring; the first mode
    also compiles the shared stages), and the total from start to the last step.

    ``cold`` runs with a fresh, empty numba cache (a temporary directory); ``cached`` with the
    core's own cache directory, so run it after the kernels have been used once."""
    out = {}
    for phase in phases:
        with tempfile.TemporaryDirectory(prefix="stelkropp-bench-cache-") as tmp:
            env = dict(os.environ)
            if phase == "cold":
                env["STELKROPP_CACHE_DIR"] = tmp
                env.pop("NUMBA_CACHE_DIR", None)
            t = time.perf_counter()
            try:
                p = subprocess.run([sys.executable, "-c", _COMPILE_SCRIPT, ",".join(modes)], env=env,
                                   capture_output=True, text=True, timeout=timeout, cwd=str(ROOT))
                line = [ln for ln in p.stdout.splitlines() if ln.startswith("@@")]
                out[phase] = json.loads(line[-1][2:]) if line else {"error": p.stderr[-500:]}
            except subprocess.TimeoutExpired:
                out[phase] = {"error": f"timeout after {timeout} s"}
            out[phase]["process_s"] = time.perf_counter() - t
            out[phase]["source_hash"] = source_hash()
    return out
