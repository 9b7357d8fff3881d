"""The sandbox in a real window (Xvfb + Mesa), driven by real X events (xdotool)."""
from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

import physics

from sandbox_pixels import ROOT, body_pixels, orange_pixels, red_text_pixels

pytestmark = pytest.mark.app

SHIPPED = sorted(p for p in (ROOT / "scenes").glob("*.json") if not p.name.endswith(".schema.json"))


def one_box_scene(path):
    w = physics.World()
    w.add_body(physics.Polygon.box(16, 1), kind="static", position=(0, -0.5), name="ground")
    w.add_body(physics.Polygon.box(1.2, 1.2), position=(0, 0.6), name="box")
    w.save_scene(str(path))
    return path


def body(st, name):
    return next(b for b in st["bodies"] if b["name"] == name)


def test_scene_appears(launch):
    app = launch(None)            # scenes/default.json
    st = app.wait_ready(30)
    assert st["path"].endswith("default.json")
    assert st["n_bodies"] > 0 and not st["gl_errors"] and not st["fault"]
    img = app.screenshot("default")
    assert body_pixels(img) > 2000, "no bodies drawn in the scene area"
    # the panels are drawn too (imgui's window background differs from the scene background)
    assert img[400, 100].tolist() != img[400, 640].tolist()


def test_drag_moves_body_and_throws_it(launch, tmp_path):
    app = launch(one_box_scene(tmp_path / "one_box.json"))
    st = app.wait_ready(30)
    b0 = body(st, "box")
    start = b0["screen"]
    up = min(220.0, start[1] - 90.0)            # stay inside the window at any zoom
    end = (start[0] + 160, start[1] - up)       # up and to the right
    m = 1.0 / st["camera"]["scale"]             # metres per pixel
    app.drag(start, end, steps=25, hold=1.0)
    st = app.frames(5)
    b1 = body(st, "box")
    # the soft mouse joint pulled the box towards the cursor (it hangs a little below it)
    assert b1["position"][1] > b0["position"][1] + 0.5 * up * m, (b0, b1)
    assert b1["position"][0] > b0["position"][0] + 0.5 * 160 * m, (b0, b1)
    sx, sy = map(int, b1["screen"])
    img = app.screenshot("dragging")
    assert orange_pixels(img, sx - 20, sy - 20, sx + 20, sy + 20) > 200, "the selected box is not drawn where it is"
    assert orange_pixels(img, int(start[0]) - 20, int(start[1]) - 20, int(start[0]) + 20, int(start[1]) - 2) < 20
    # release while moving fast to the right: the box flies on (thrown), then falls back down
    app.xdo("mousemove", int(end[0] + 120), int(end[1]))
    app.settle()                                # the joint pulls the box along for a few frames
    app.xdo("mouseup", 1)
    st = app.frames(40)
    b2 = next((b for b in st["bodies"] if b["name"] == "box"), None)
    if b2 is None:       # thrown beyond the world bound (issue 16, item 4): removed with a notice
        assert any("left the world bound" in m for m in st["messages"]), st["messages"]
    else:
        assert b2["position"][0] > b1["position"][0] + 1.0, (b1, b2)
    assert not st["gl_errors"] and not st["fault"]


def test_create_box_undo_redo(launch, tmp_path):
    app = launch(one_box_scene(tmp_path / "one_box.json"), "--paused")
    st = app.wait_ready(20)
    n0 = st["n_bodies"]
    ground = body(st, "ground")["screen"]
    before = app.screenshot("before_box")
    app.key("2")                                   # the box tool
    app.frames(3)
    x0, y0 = int(ground[0]) + 60, int(ground[1]) - 200
    app.drag((x0, y0), (x0 + 90, y0 + 70), steps=10)
    app.xdo("mouseup", 1)
    st = app.frames(5)
    assert st["n_bodies"] == n0 + 1, st["messages"]
    assert st["dirty"]
    img = app.screenshot("after_box")
    # the new box is drawn (selected: orange) where it was dragged out
    assert orange_pixels(img, x0 + 10, y0 + 10, x0 + 80, y0 + 60) > 1500
    assert orange_pixels(before, x0 + 10, y0 + 10, x0 + 80, y0 + 60) == 0
    app.key("ctrl+z")
    st = app.frames(5)
    assert st["n_bodies"] == n0
    app.key("ctrl+shift+z")
    st = app.frames(5)
    assert st["n_bodies"] == n0 + 1


def test_switch_solver_mid_run(launch):
    app = launch(None)
    st = app.wait_ready(30)
    modes = [k.split(":", 1)[1] for k in st["ui_rects"] if k.startswith("solver:")]
    x0, y0, x1, y1 = st["ui_rects"]["solver_combo"]
    app.click((x0 + x1) / 2, (y0 + y1) / 2)
    st = app.frames(5)
    others = [k for k in st["ui_rects"] if k.startswith("solver:") and k != f"solver:{st['solver']}"]
    assert others, f"the solver combo lists only {st['ui_rects'].keys()}"
    target = others[0].split(":", 1)[1]
    x0, y0, x1, y1 = st["ui_rects"][others[0]]
    app.click((x0 + x1) / 2, (y0 + y1) / 2)
    # the new mode's kernels load (or compile) first while the scene runs on; then it switches
    st = app.wait(lambda s: s["solver"] == target, 600, f"solver {target}")
    steps = st["steps"]
    st = app.wait(lambda s: s["steps"] > steps + 30, 600, "stepping with the new solver")
    assert not st["gl_errors"] and not st["fault"], st
    img = app.screenshot("switched")
    assert body_pixels(img) > 2000


def test_bad_file_keeps_scene_and_shows_error(launch, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"format": "stelkropp-scene", "bodies": [{"shape": {"box": [-1, 2]},
                                                                         "position": [0, "x"]}]}))
    app = launch(None)
    st = app.wait_ready(30)
    n0, path0 = st["n_bodies"], st["path"]
    before = app.screenshot("before_bad")
    app.send("on_file_drop", 640, 400, [str(bad)])      # as a file dropped on the window
    st = app.wait(lambda s: s["scene_errors"], 20, "the scene error")
    st = app.settle()               # the error window is placed once imgui knows its size
    assert st["n_bodies"] == n0 and st["path"] == path0
    assert any("bad.json" in line for line in st["scene_errors"])
    img = app.screenshot("after_bad")
    assert body_pixels(img) > 0.5 * body_pixels(before)
    x0, y0, x1, y1 = map(int, st["ui_rects"]["scene_errors"])
    assert red_text_pixels(img, x0, y0, x1, y1) > 100, "the error is not shown"
    # a file that is not JSON at all
    junk = tmp_path / "junk.json"
    junk.write_text("{ this is not json")
    app.send("on_file_drop", 640, 400, [str(junk)])
    st = app.wait(lambda s: any("junk.json" in line for line in s["scene_errors"]), 20, "the junk error")
    assert st["n_bodies"] == n0 and not st["gl_errors"]


@pytest.fixture(scope="module")
def tour(app_env, tmp_path_factory):
    """Every shipped scene opened in turn in one sandbox (``--tour``: the scene panel's way of
    opening a scene), 120 frames and 5 simulated seconds each: (exit status and output, the folder
    of <scene>.png and <scene>.json, each json the status at that scene's last frame with its own
    errors)."""
    out = tmp_path_factory.mktemp("tour")
    r = subprocess.run([sys.executable, "-m", "app", str(SHIPPED[0]), "--frames", "120", "--screenshot", str(out),
                        "--tour", *map(str, SHIPPED[1:]), "--tour-seconds", "5", "--no-autosave-offer"],
                       cwd=ROOT, env=app_env, capture_output=True, text=True, timeout=1800)
    return r, out


@pytest.mark.slow
@pytest.mark.parametrize("scene", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_shipped_scene_renders_120_frames(scene, tour):
    r, out = tour
    assert r.returncode == 0, r.stdout + r.stderr
    shot = out / f"{scene.stem}.png"
    assert shot.is_file(), f"{scene.name} was not reached: {r.stdout + r.stderr}"
    st = json.loads(shot.with_suffix(".json").read_text())
    assert not st["gl_errors"] and not st["scene_errors"], st
    assert st["path"].endswith(scene.name)
    from PIL import Image
    img = np.asarray(Image.open(shot).convert("RGB")).astype(int)
    assert img.shape[:2] == (800, 1280)
    assert body_pixels(img, 0, 1280, 0, 800) > 300, "nothing drawn"
    # issue 16 item 5: the scene is drawn in the free area beside the panels at 1280x800
    fx0, fy0, fx1, fy1 = map(int, st["free_rect"])
    assert body_pixels(img, fx0, fx1, fy0, fy1) > 300, "nothing drawn in the free area"


@pytest.mark.slow
@pytest.mark.parametrize("scene", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_shipped_scene_stays_framed_after_5_seconds(scene, tour):
    # a new user opens a scene at 1280x800 and plays: after 5 s what it is about is still drawn in
    # the free area beside the panels (not driven or fallen out of view, not under a panel)
    r, out = tour
    st = json.loads((out / f"{scene.stem}.json").read_text())
    assert st["time"] >= 5.0 - 1e-9, st["time"]
    fr = st["framing"]
    assert fr["moving"] > 0
    assert fr["inside_free"] >= 0.9 * fr["moving"], f"{scene.stem}: {fr['inside_free']} of {fr['moving']} in view"
    x0, y0, x1, y1 = st["free_rect"]
    assert 0 <= x0 < x1 <= 1280 and 0 <= y0 < y1 <= 800


@pytest.mark.slow
@pytest.mark.parametrize("scene", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_shipped_scene_caption_in_the_free_area(scene, tour):
    # a scene whose description says what to try shows that sentence at the top of the free area
    # (inside it, clear of the panels); the others show none
    from app.scene_caption import caption_of
    r, out = tour
    st = json.loads((out / f"{scene.stem}.json").read_text())
    want = caption_of(json.loads(scene.read_text()))
    assert st["ui_values"].get("caption") == want
    if want is None:
        assert "caption" not in st["ui_rects"]
        return
    x0, y0, x1, y1 = st["ui_rects"]["caption"]
    fx0, fy0, fx1, fy1 = st["free_rect"]
    assert fx0 <= x0 < x1 <= fx1 and fy0 <= y0 < y1 <= fy1, (st["ui_rects"]["caption"], st["free_rect"])
