"""``python -m bench.compile_cost``: the CPU seconds a cold numba cache costs, as a user meets them.

One new process with an empty cache (a temporary directory) opens the default scene and steps
it (the first launch's wait), then opens each of six shipped scenes and steps it three times in
each of the five modes, in that order, so each figure is what that scene or mode adds to what
was compiled before it.  CPU time, not wall time: a second job on the machine slows the wall
clock but not the compile's own CPU seconds much.  Prints each figure as it comes (the run
takes minutes) and writes ``compile_cost.json`` into ``--out`` (default bench/results/).
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

from .paths import RESULTS, ROOT

SCENES = ("default", "pendulum", "capsules", "car", "chain_bridge", "compounds")
MODES = ("soft_step", "sequential_impulse", "impulse", "penalty", "hybrid")

_SCRIPT = r"""
import json, sys, time
c0 = time.process_time()
import physics
from physics.scene import load_scene
print("@@" + json.dumps({"what": "import", "cpu_s": time.process_time() - c0}), flush=True)
for scene in sys.argv[1].split(","):
    w = load_scene(f"scenes/{scene}.json")
    for mode in ["default"] + sys.argv[2].split(","):
        if mode != "default":
            w.solver = mode
        t = time.process_time()
        for _ in range(3):
            w.step()
        print("@@" + json.dumps({"what": f"{scene}:{mode}", "cpu_s": time.process_time() - t}), flush=True)
print("@@" + json.dumps({"what": "total", "cpu_s": time.process_time() - c0}), flush=True)
"""


def run(scenes=SCENES, modes=MODES, timeout=3600) -> list[dict]:
    """The figures of one cold process, in the order they came."""
    rows = []
    with tempfile.TemporaryDirectory(prefix="stelkropp-compile-") as tmp:
        env = dict(os.environ, STELKROPP_CACHE_DIR=tmp)
        env.pop("NUMBA_CACHE_DIR", None)
        p = subprocess.Popen([sys.executable, "-c", _SCRIPT, ",".join(scenes), ",".join(modes)], env=env,
                             cwd=str(ROOT), stdout=subprocess.PIPE, text=True)
        for line in p.stdout:
            if line.startswith("@@"):
                rows.append(json.loads(line[2:]))
                print(f"{rows[-1]['what']:>34s} {rows[-1]['cpu_s']:7.1f} CPU s", flush=True)
        p.wait(timeout=timeout)
    return rows


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m bench.compile_cost", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", type=Path, default=RESULTS)
    ap.add_argument("--scenes", default=",".join(SCENES))
    a = ap.parse_args(argv)
    rows = run(a.scenes.split(","))
    first = next((r["cpu_s"] for r in rows if r["what"].endswith(":default")), None)
    total = next((r["cpu_s"] for r in rows if r["what"] == "total"), None)
    print(f"default scene's first steps {first:.1f} CPU s; every scene and mode {total:.1f} CPU s")
    a.out.mkdir(parents=True, exist_ok=True)
    (a.out / "compile_cost.json").write_text(json.dumps({"rows": rows, "first_scene_cpu_s": first,
                                                         "total_cpu_s": total}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
