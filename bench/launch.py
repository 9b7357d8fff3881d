"""``python -m bench.launch``: how long a new user waits, in a real sandbox window under Xvfb.

Starts ``python -m app SCENE`` (a real window; Xvfb is started when DISPLAY is unset), reads the
status file it writes every other frame, and prints, from the process start:

- ``drawn``: the first frame is on screen (the sandbox draws the scene, paused, before any
  kernel is compiled; an older sandbox drew nothing until its kernels were ready, so for it this
  is the same moment as ``ready``);
- ``ready``: the open scene's kernels are loaded;
- ``playing``: the world has taken its first step;

each with the CPU seconds the sandbox process and its compiler process (a child, on the other
core) had used by then: on this shared machine the wall times stretch with the load, the CPU
seconds much less (the larger of the two is about what an idle machine waits).

``cold`` runs with an empty cache directory (``STELKROPP_CACHE_DIR``, fresh each repeat);
``cached`` right after it with the same directory.  The machine's load average (``uptime``) is
printed with every run: on a shared machine the absolute times mean little without it, so
``--app-root`` runs another checkout's sandbox interleaved with this one (before/after ratios).

    python -m bench.launch                       # cold, then cached, scenes/default.json
    python -m bench.launch --phases cached --repeat 3
    python -m bench.launch --app-root /work/main --repeat 1    # interleaved with main's sandbox
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from .paths import ROOT
from .xvfb import start_xvfb


def load() -> str:
    """The 1-minute load average and the core count (shared machines: read times with it)."""
    return f"load {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores"


def cpu_seconds(pid: int) -> tuple[float, float]:
    """(CPU seconds of process ``pid``, of its live children) from /proc (Linux; 0 elsewhere).
    On a loaded machine wall times stretch with the load; the CPU seconds of the sandbox (and
    of its compiler process, on the other core) are what an idle machine would wait."""
    tick = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100

    def one(p):
        try:
            f = Path(f"/proc/{p}/stat").read_text().rsplit(")", 1)[1].split()
            return (int(f[11]) + int(f[12])) / tick
        except (OSError, IndexError, ValueError):
            return 0.0
    kids = []
    try:
        for t in Path(f"/proc/{pid}/task").iterdir():
            kids += [int(k) for k in (t / "children").read_text().split()]
    except OSError:
        pass
    return one(pid), sum(one(k) for k in kids)


def _status(path: Path) -> dict:
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        return {}


def launch_once(app_root: Path, scene: str, cache: Path, display: str, timeout: float) -> dict:
    """One sandbox launch; seconds from the process start to drawn / ready / playing."""
    with tempfile.TemporaryDirectory(prefix="stelkropp-launch-") as tmp:
        st_path = Path(tmp) / "status.json"
        unit_log = Path(tmp) / "units.txt"
        env = dict(os.environ, DISPLAY=display, STELKROPP_CACHE_DIR=str(cache), XDG_DATA_HOME=tmp,
                   XDG_STATE_HOME=tmp, STELKROPP_UNIT_LOG=str(unit_log))
        env.pop("NUMBA_CACHE_DIR", None)
        cmd = [sys.executable, "-m", "app", scene, "--position", "0,0", "--size", "1280x800",
               "--status", str(st_path), "--no-autosave-offer"]
        out = {"load_before": load()}
        seen = set()
        t0, wall0 = time.monotonic(), time.time()
        proc = subprocess.Popen(cmd, cwd=app_root, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                text=True)
        try:
            while time.monotonic() - t0 < timeout:
                if proc.poll() is not None:
                    out["error"] = f"exited {proc.returncode}: {proc.stderr.read()[-800:]}"
                    break
                st = _status(st_path)
                t = time.monotonic() - t0
                if st.get("frame", 0) >= 1 and "drawn" not in out:
                    out["drawn"], out["cpu_drawn"] = t, cpu_seconds(proc.pid)
                    # an older sandbox has no progress field and draws no scene before it is ready
                    out["scene_before_ready"] = "progress" in st
                if "progress" in st and not st.get("ready"):
                    seen.add(round(st["progress"], 3))
                if st.get("ready") and "ready" not in out:
                    out["ready"], out["cpu_ready"] = t, cpu_seconds(proc.pid)
                if st.get("ready") and st.get("steps", 0) > 0:
                    out["playing"], out["cpu_playing"] = t, cpu_seconds(proc.pid)
                    break
                time.sleep(0.05)
            else:
                out["error"] = f"not playing after {timeout:.0f} s"
        finally:
            proc.terminate()
            try:
                proc.wait(10)
            except subprocess.TimeoutExpired:
                proc.kill()
        out["progress_values"] = len(seen)
        out["load_after"] = load()
        out["units"] = _units(unit_log, proc.pid, wall0)
        return out


def _units(path: Path, pid: int, wall0: float) -> list:
    """The compile units of one launch (app.compile_units.run's log): [process ("sandbox" or
    "helper"), unit, start s, end s after the launch, CPU s], in start order."""
    rows = []
    try:
        for ln in path.read_text().splitlines():
            p, unit, a, b, c0, c1 = ln.split()
            rows.append(["sandbox" if int(p) == pid else "helper", unit, float(a) - wall0, float(b) - wall0,
                         float(c1) - float(c0)])
    except (OSError, ValueError):
        return []
    return sorted(rows, key=lambda r: r[2])


def _timeline(r: dict) -> str:
    """The units that ended before the scene played, one line each."""
    end = r.get("playing", float("inf"))
    return "\n".join(f"{'':>21}{who:>8} {unit:<40} {a:6.1f} -> {b:6.1f} s  cpu {c:5.1f}"
                     for who, unit, a, b, c in r.get("units", []) if b <= end)


def _fmt(r: dict) -> str:
    if "error" in r:
        return f"ERROR {r['error']}"
    parts = [f"{k} {r[k]:6.1f} s (cpu {r['cpu_' + k][0]:.1f} + {r['cpu_' + k][1]:.1f})"
             for k in ("drawn", "ready", "playing") if k in r]
    note = "" if r.get("scene_before_ready", True) else "  (drawn: an empty first frame, the scene only when ready)"
    return "  ".join(parts) + f"  ({r['progress_values']} progress values){note}  " \
        f"[{r['load_before']} -> {r['load_after']}]"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m bench.launch", description=__doc__.split("\n\n")[0])
    ap.add_argument("--scene", default="scenes/default.json")
    ap.add_argument("--phases", default="cold,cached", help="comma list of cold, cached")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--app-root", action="append", default=[],
                    help="also launch this checkout's sandbox, interleaved (repeatable)")
    ap.add_argument("--timeout", type=float, default=1500)
    ap.add_argument("--json", default=None, help="write the results here")
    ap.add_argument("--cache-root", default=None,
                    help="use this cache root as it is (kept; no cold fill before 'cached')")
    args = ap.parse_args(argv)
    roots = [ROOT] + [Path(r).resolve() for r in args.app_root]
    xvfb = None
    display = os.environ.get("DISPLAY")
    if not display:
        xvfb, display = start_xvfb()
    results = []
    try:
        for rep in range(args.repeat):
            for root in roots:
                given = args.cache_root is not None
                cache = Path(args.cache_root) if given else Path(tempfile.mkdtemp(prefix="stelkropp-launch-cache-"))
                try:
                    phases = args.phases.split(",")
                    if phases[0] == "cached" and not given:      # fill the cache first (not reported)
                        launch_once(root, args.scene, cache, display, args.timeout)
                    for phase in phases:
                        r = launch_once(root, args.scene, cache, display, args.timeout)
                        r.update(root=str(root), phase=phase, repeat=rep)
                        results.append(r)
                        print(f"{root.name:>12} {phase:>6}: {_fmt(r)}", flush=True)
                        if phase == "cold" and r.get("units"):
                            print(_timeline(r), flush=True)
                finally:
                    if not given:
                        shutil.rmtree(cache, ignore_errors=True)
    finally:
        if xvfb is not None:
            xvfb.terminate()
    if args.json:
        Path(args.json).write_text(json.dumps(results, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
