"""Sandbox tests: a real window under Xvfb (Mesa llvmpipe), real input through xdotool.

If DISPLAY is unset, an Xvfb server is started on a free display number for the
session.  Missing tools (Xvfb, xdotool, ImageMagick's import) make the tests
FAIL with a message saying what to install: they are never skipped silently.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from bench.xvfb import start_xvfb

ROOT = Path(__file__).resolve().parents[2]
INSTALL = ("apt-get install -y xvfb xauth libgl1-mesa-dri libegl1 libegl-mesa0 libglu1-mesa "
           "x11-utils imagemagick mesa-utils xdotool")
# a cold numba cache compiles every kernel on first launch
READY_TIMEOUT = float(os.environ.get("STELKROPP_APP_READY_TIMEOUT", 900))


def _need(tool):
    if shutil.which(tool) is None:
        pytest.fail(f"sandbox tests need `{tool}` (not found on PATH); install with: {INSTALL}", pytrace=False)


@pytest.fixture(scope="session")
def display():
    _need("xdotool")
    _need("import")
    if os.environ.get("DISPLAY"):
        yield os.environ["DISPLAY"]
        return
    _need("Xvfb")
    try:
        proc, name = start_xvfb()
    except RuntimeError as exc:
        pytest.fail(str(exc), pytrace=False)
    yield name
    proc.terminate()
    try:
        proc.wait(5)
    except subprocess.TimeoutExpired:
        proc.kill()


@pytest.fixture(scope="session")
def app_env(display, tmp_path_factory):
    env = dict(os.environ)
    env["DISPLAY"] = display
    env.pop("PYOPENGL_PLATFORM", None)
    cache = tmp_path_factory.mktemp("cache")
    env["XDG_CACHE_HOME"] = str(cache)
    # the sandbox loads the kernels from the cache the tests (and `python -m physics precompile`)
    # filled, also where a test gives it its own XDG_CACHE_HOME (autosaves): the window tests
    # check the sandbox, not numba's compiler (tests/app/test_launch.py times a cold launch)
    from physics import _jit  # sets NUMBA_CACHE_DIR (this source's cache) unless the user chose one
    env["STELKROPP_CACHE_DIR"] = str(_jit._cache_root())
    if os.environ.get("NUMBA_CACHE_DIR"):
        env["NUMBA_CACHE_DIR"] = os.environ["NUMBA_CACHE_DIR"]
    return env


class AppProc:
    """One sandbox process at the top-left corner of the Xvfb screen."""

    def __init__(self, env, tmp: Path, scene=None, args=(), offer_autosave=False):
        self.env = env
        self.tmp = tmp
        self.user_scenes = Path(env.get("XDG_DATA_HOME", tmp / "data")) / "stelkropp" / "scenes"
        self.status_file = tmp / "status.json"
        self.control_file = tmp / "control.jsonl"
        tmp.mkdir(parents=True, exist_ok=True)
        self.control_file.write_text("")
        cmd = [sys.executable, "-m", "app"] + ([str(scene)] if scene else []) + [
            "--position", "0,0", "--size", "1280x800", "--status", str(self.status_file),
            "--control", str(self.control_file), *([] if offer_autosave else ["--no-autosave-offer"]), *args]
        self.log = open(tmp / "app.log", "w")
        self.proc = subprocess.Popen(cmd, cwd=ROOT, env=env, stdout=self.log, stderr=subprocess.STDOUT)

    def status(self) -> dict:
        try:
            return json.loads(self.status_file.read_text())
        except (OSError, ValueError):
            return {}

    def wait(self, cond, timeout=60.0, what="condition"):
        t0 = time.monotonic()
        while time.monotonic() - t0 < timeout:
            if self.proc.poll() is not None:
                raise AssertionError(f"sandbox exited with {self.proc.returncode}:\n{self.logtext()}")
            st = self.status()
            if st and cond(st):
                return st
            time.sleep(0.1)
        raise AssertionError(f"timed out waiting for {what}; last status: "
                             f"{ {k: v for k, v in self.status().items() if k != 'bodies'} }\n{self.logtext()}"
                             f"\n{self.x_state()}")

    def wait_ready(self, frames=20, joints=True):
        """Wait until the scene runs (and, with ``joints``, the mode's joint stage is loaded too: a
        scene without joints plays before it, and a test's first drag would wait for it)."""
        st = self.wait(lambda s: s.get("ready") and (s.get("joints_ready") or not joints), READY_TIMEOUT,
                       "the kernels to compile")
        f0 = st["frame"]
        return self.wait(lambda s: s["frame"] >= f0 + frames, 60, f"{frames} frames")

    def frames(self, n=10):
        f0 = self.status().get("frame", 0)
        return self.wait(lambda s: s["frame"] >= f0 + n, 60, f"{n} more frames")

    def settle(self):
        """Wait until the window has run a whole frame after this call, so input sent before it
        has been handled.  The status file is written every `status_every` frames, so the write
        read now may be that many frames old: two periods later a frame that began after this
        call has certainly ended.  (A person's click lasts several frames; on a loaded machine
        xdotool's move, press and release would otherwise land in one slow frame.)"""
        st = self.status()
        period = st.get("status_every", 5)
        return self.frames(2 * period)

    def xdo(self, *args):
        subprocess.run(["xdotool", *map(str, args)], env=self.env, check=True, timeout=30)

    def drag(self, start, end, steps=20, hold=0.0, button=1):
        self.xdo("mousemove", int(start[0]), int(start[1]))
        self.settle()
        self.xdo("mousedown", button)
        self.settle()
        for i in range(1, steps + 1):
            x = start[0] + (end[0] - start[0]) * i / steps
            y = start[1] + (end[1] - start[1]) * i / steps
            self.xdo("mousemove", int(x), int(y))
            time.sleep(0.03)
        time.sleep(hold)

    def click(self, x, y):
        """Move there, press, release: each seen by the window in its own frame."""
        self.xdo("mousemove", int(x), int(y))
        self.settle()
        self.xdo("mousedown", 1)
        self.settle()
        self.xdo("mouseup", 1)

    def key(self, *keys):
        self.xdo("key", *keys)

    def set_time_scale(self, value):
        """Type ``value`` into the simulation panel's time-scale slider (Ctrl+click, as a person
        would), so a long play takes less real time; the world steps the same ``dt`` whatever
        the scale.  Returns the status once the scale is taken."""
        st = self.settle()
        x0, y0, x1, y1 = st["ui_rects"]["sim:time_scale"]
        self.xdo("keydown", "ctrl")
        self.click(int((x0 + x1) / 2), int((y0 + y1) / 2))
        self.xdo("keyup", "ctrl")
        self.settle()
        self.xdo("type", "--delay", "30", f"{value:g}")
        self.key("Return")
        return self.wait(lambda s: abs(s["time_scale"] - value) < 1e-9, 10, f"the time scale {value:g}")

    def send(self, event, *args):
        with open(self.control_file, "a") as f:
            f.write(json.dumps({"event": event, "args": list(args)}) + "\n")

    def screenshot(self, name) -> np.ndarray:
        from PIL import Image
        path = self.tmp / f"{name}.png"
        subprocess.run(["import", "-window", "root", str(path)], env=self.env, check=True, timeout=30)
        return np.asarray(Image.open(path).convert("RGB")).astype(int)

    def x_state(self) -> str:
        """The pointer and the X windows (for a failure message; the screen is saved as timeout.png)."""
        out = []
        for cmd in (["xdotool", "getmouselocation"], ["xwininfo", "-root", "-tree"]):
            try:
                r = subprocess.run(cmd, env=self.env, capture_output=True, text=True, timeout=10)
                out.append(r.stdout.strip()[-2000:])
            except (OSError, subprocess.SubprocessError) as exc:
                out.append(f"{cmd[0]}: {exc}")
        try:
            subprocess.run(["import", "-window", "root", str(self.tmp / "timeout.png")], env=self.env, timeout=30)
        except (OSError, subprocess.SubprocessError):
            pass
        return "\n".join(out)

    def logtext(self):
        self.log.flush()
        return (self.tmp / "app.log").read_text()[-4000:]

    def close(self):
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
        self.log.close()


@pytest.fixture
def launch(app_env, tmp_path):
    procs = []

    def _launch(scene=None, *args, offer_autosave=False, env=None, subdir=None):
        # the user's scene folder (platformdirs' user data dir) is the test's own
        env = dict(app_env, XDG_DATA_HOME=str(tmp_path / "data"), **(env or {}))
        p = AppProc(env, tmp_path / subdir if subdir else tmp_path, scene, args, offer_autosave)
        procs.append(p)
        return p
    yield _launch
    for p in procs:
        p.close()




def pytest_collection_modifyitems(config, items):
    """Run the window tests on one xdist worker, one at a time (`--dist loadgroup`): two sandboxes
    drawing on llvmpipe at once would each get half a core, and their frame-timed waits would
    measure the other's load; the physics tests share out the other worker."""
    for item in items:
        if "tests/app/" in str(item.fspath).replace("\\", "/"):
            item.add_marker(pytest.mark.xdist_group("app"))
