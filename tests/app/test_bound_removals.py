"""The world bound's removals are the sandbox's doing, not the user's edits: a shipped scene loses
no bodies in normal play, a removal leaves the document clean (another scene opens without a
question), and its undo brings a body back inside the bound, at rest."""
from __future__ import annotations

import pytest

from sandbox_pixels import ROOT, body_pixels
from test_saving import centre, scene_point
from test_tools import body, to_screen
from test_world_bound import RUNNER_SCENE_BODIES, runner_scene

pytestmark = pytest.mark.app


@pytest.mark.slow
def test_soft_body_keeps_its_bodies(launch):
    app = launch(ROOT / "scenes" / "soft_body.json")
    st0 = app.wait_ready(2)
    n0 = st0["n_bodies"]
    app.set_time_scale(4)   # the slider's top: 20 simulated seconds in about 5 real ones
    # the blobs land, slide off the wedge and roll to the ends of the ground (it took ~10 s to lose one)
    st = app.wait(lambda s: s["time"] >= 20.0 or s["n_bodies"] != n0, 600, "20 s of simulated time")
    assert st["n_bodies"] == n0, [m for m in st["messages"] if "world bound" in m]
    assert not st["dirty"]
    img = app.screenshot("soft_body_20s")
    fx0, fy0, fx1, fy1 = map(int, st["free_rect"])
    assert body_pixels(img, fx0, fx1, fy0, fy1, static=False) > 500, "the blobs are not in view"


def test_a_removal_leaves_the_document_clean(launch, tmp_path):
    app = launch(runner_scene(tmp_path / "runner.json"))
    st0 = app.wait_ready(2)
    n0 = RUNNER_SCENE_BODIES
    assert st0["n_bodies"] == n0, "the runner left before the sandbox was ready"
    st = app.wait(lambda s: s["n_bodies"] == n0 - 1, 30, "the runner to leave the bound")
    assert not st["dirty"], "the world bound's removal marked the scene as edited"
    app.xdo("mousemove", *scene_point(st))
    app.settle()
    app.key("ctrl+shift+s")                     # opens the Scene section (its list of scenes)
    app.settle()
    app.key("Escape")
    arch = ROOT / "scenes" / "arch.json"
    st = app.wait(lambda s: f"scene:{arch}" in s["ui_rects"], 10, "arch.json in the scene list")
    x, y = centre(st["ui_rects"][f"scene:{arch}"])
    app.xdo("mousemove", x, y)
    app.settle()
    app.xdo("click", "--repeat", "2", "--delay", "80", "1")
    st = app.wait(lambda s: s["path"] == str(arch) or s["dialog"], 20, "arch.json to open")
    assert st["dialog"] is None and st["path"] == str(arch), f"asked: {st['dialog']}"
    assert not st["dirty"]


def test_undo_of_a_removal_brings_the_body_back_inside_at_rest(launch, tmp_path):
    app = launch(runner_scene(tmp_path / "runner.json"))
    st0 = app.wait_ready(2)
    n0 = RUNNER_SCENE_BODIES
    assert st0["n_bodies"] == n0, "the runner left before the sandbox was ready"
    lo, hi = st0["bound"]["lo"], st0["bound"]["hi"]
    app.wait(lambda s: s["n_bodies"] == n0 - 1, 30, "the runner to leave the bound")
    app.xdo("mousemove", *scene_point(st0))
    app.settle()
    app.key("space")                            # pause
    app.key("ctrl+z")
    st = app.wait(lambda s: s["n_bodies"] == n0, 10, "the runner back")
    r = body(st, "runner")
    assert lo[0] <= r["position"][0] <= hi[0] and lo[1] <= r["position"][1] <= hi[1], r["position"]
    assert r["velocity"] == pytest.approx([0.0, 0.0]) and r["angular_velocity"] == pytest.approx(0.0)
    assert r["position"][0] > hi[0] - 3.0, "not where it was last inside"
    # it is drawn where it is, and playing on it stays (at rest on nothing, it falls inside the bound)
    img = app.screenshot("runner_back")
    x, y = map(int, to_screen(st, r["position"]))
    assert body_pixels(img, x - 6, x + 6, y - 6, y + 6, static=False) > 50, "the runner is not drawn"
    app.key("space")
    st = app.frames(30)
    assert st["n_bodies"] == n0
