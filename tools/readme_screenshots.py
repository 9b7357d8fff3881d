"""Take the README's screenshots again from the sandbox as it is now: ``python -m tools.readme_screenshots
[screenshot] [compare]`` (both unless named).

docs/screenshot.png: the default scene at 1280x800 after its shower of shapes has settled (about
6 s).  docs/compare.png: scenes/pyramid.json compared live with sequential_impulse in the split
view, 12 s after the comparison began.  Both are taken under a private Xvfb server (or $DISPLAY if set) with real
X input (xdotool), as the window tests drive the sandbox (tests/app/conftest.py's AppProc), so a
panel moved or renamed shows up here as it does there.  Needs Xvfb, xdotool and ImageMagick."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "app"))

from conftest import AppProc  # noqa: E402  (the window tests' driver)

SETTLE_SECONDS = 6.0        # the default scene's shower has landed and the stats show it
COMPARE_SECONDS = 12.0      # the plots (20 s wide) show the rivals' start and the steady run after


def centre(rect):
    x0, y0, x1, y1 = rect
    return int((x0 + x1) / 2), int((y0 + y1) / 2)


def xvfb():
    """(display, process or None): $DISPLAY, else a new Xvfb server at 1280x800."""
    if os.environ.get("DISPLAY"):
        return os.environ["DISPLAY"], None
    n = next(k for k in range(120, 400) if not Path(f"/tmp/.X11-unix/X{k}").exists()
             and not Path(f"/tmp/.X{k}-lock").exists())
    proc = subprocess.Popen(["Xvfb", f":{n}", "-screen", "0", "1280x800x24", "-nolisten", "tcp"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for _ in range(200):
        if Path(f"/tmp/.X11-unix/X{n}").exists():
            return f":{n}", proc
        time.sleep(0.1)
    raise RuntimeError("Xvfb did not start")


def shoot(app, name, out: Path):
    app.xdo("mousemove", 1279, 799)      # no hover highlight on a button or a body
    app.settle()
    app.screenshot(name)
    shutil.copy(app.tmp / f"{name}.png", out)
    print("wrote", out)


def default_scene(env, tmp: Path):
    app = AppProc(env, tmp / "default", ROOT / "scenes" / "default.json")
    try:
        app.wait_ready(20)
        app.wait(lambda s: s["time"] > SETTLE_SECONDS, 300, "the shower settled")
        shoot(app, "screenshot", ROOT / "docs" / "screenshot.png")
    finally:
        app.close()


def comparison(env, tmp: Path):
    app = AppProc(env, tmp / "compare", ROOT / "scenes" / "pyramid.json")
    try:
        st = app.wait_ready(20)
        app.click(*centre(st["ui_rects"]["section:Compare solvers"]))
        st = app.settle()
        app.click(*centre(st["ui_rects"]["compare:mode:sequential_impulse"]))
        st = app.settle()
        app.click(*centre(st["ui_rects"]["compare:start"]))
        t0 = app.wait(lambda s: s["compare"]["active"], 900, "the comparison")["time"]
        st = app.wait(lambda s: len(s["compare"]["lanes"]) == 2 and s["compare"]["lanes"][1]["steps"] > 30,
                      900, "the rival stepping")
        app.click(*centre(st["ui_rects"]["compare:view:split"]))
        app.wait(lambda s: s["compare"]["view"] == "split", 10, "the split view")
        app.wait(lambda s: s["time"] > t0 + COMPARE_SECONDS, 600, "the plots filled")
        shoot(app, "compare", ROOT / "docs" / "compare.png")
    finally:
        app.close()


def main(wanted=()) -> int:
    display, server = xvfb()
    from physics import _jit
    env = dict(os.environ, DISPLAY=display, STELKROPP_CACHE_DIR=str(_jit._cache_root()))
    env.pop("PYOPENGL_PLATFORM", None)
    try:
        with tempfile.TemporaryDirectory() as tmp:
            env["XDG_DATA_HOME"] = str(Path(tmp) / "data")
            env["XDG_CACHE_HOME"] = str(Path(tmp) / "cache")
            for name, take in (("screenshot", default_scene), ("compare", comparison)):
                if not wanted or name in wanted:
                    take(env, Path(tmp))
    finally:
        if server is not None:
            server.terminate()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
