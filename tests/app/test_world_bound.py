"""Issue 16, item 4: a world bound, shown and editable, from the scene's extent; a body that
crosses it is removed with a notice and an undo; F frames the scene's content, not escapees."""
from __future__ import annotations

import json

import numpy as np
import pytest

from test_saving import centre
from test_tools import to_screen

pytestmark = pytest.mark.app


#: the bodies of runner_scene: ground, stay, runner
RUNNER_SCENE_BODIES = 3


def runner_scene(path):
    data = {"format": "stelkropp.scene", "version": 1, "name": "runner",
            "camera": {"center": [0.0, 3.0], "zoom": 20.0},
            "bodies": [
                {"name": "ground", "kind": "static", "shape": {"box": [16, 1]}, "position": [0, -0.5]},
                {"name": "stay", "shape": {"box": [1, 1]}, "position": [-3, 0.5]},
                # 12 m/s: off the ground's end at x = 8 m, out through the bound's side (x = 18 m) about
                # 1.1 s in, after the sandbox is ready (0.4 s here), so the tests see all three bodies first
                {"name": "runner", "shape": {"box": [1, 1]}, "position": [5, 0.5], "velocity": [12, 0],
                 "friction": 0.05},
            ]}
    path.write_text(json.dumps(data))
    return path


def amber_column(img, x, y0, y1) -> int:
    """Bound-coloured pixels (orange, alpha 0.55 over the dark background) in columns x-2..x+2."""
    a = img[y0:y1, max(0, x - 2):x + 3]
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    return int(np.count_nonzero((r > 110) & (r - b > 60) & (g > 60) & (g < r)))


def test_bodies_that_leave_the_bound_are_removed_with_an_undo(launch, tmp_path):
    app = launch(runner_scene(tmp_path / "runner.json"))
    st0 = app.wait_ready(2)
    lo, hi = st0["bound"]["lo"], st0["bound"]["hi"]
    # from the extent (ground 16 m x 1.5 m, stay and runner): 10 m beyond it, 20 m above
    assert lo == pytest.approx([-18.0, -11.0], abs=0.05) and hi == pytest.approx([18.0, 21.0], abs=0.05), st0["bound"]  # AABBs carry a 1 cm margin
    n0 = RUNNER_SCENE_BODIES
    assert st0["n_bodies"] == n0, "the runner left before the sandbox was ready"
    st = app.wait(lambda s: s["n_bodies"] == n0 - 1, 30, "the runner to leave the bound")
    assert all(b["name"] != "runner" for b in st["bodies"])
    assert any("left the world bound" in m for m in st["messages"]), st["messages"]
    img = app.screenshot("bound")
    fx0, fy0, fx1, fy1 = map(int, st["free_rect"])
    xr = int(to_screen(st, (hi[0], 0))[0])
    xl = int(to_screen(st, (lo[0], 0))[0])
    assert fx0 < xl < xr < fx1
    assert amber_column(img, xr, fy0 + 10, fy1 - 10) > 200, "the bound's right edge is not drawn"
    assert amber_column(img, xl, fy0 + 10, fy1 - 10) > 200, "the bound's left edge is not drawn"
    # (its undo: test_bound_removals.py)
    app.xdo("mousemove", (fx0 + fx1) // 2, (fy0 + fy1) // 2)
    app.key("space")                                     # pause
    # F frames what is inside the bound: the ground fills the free area
    app.key("f")
    st = app.wait(lambda s: s["camera"]["scale"] != st0["camera"]["scale"], 10, "the fit")
    ground_px = 16.0 * st["camera"]["scale"]
    assert ground_px > 0.7 * (fx1 - fx0), f"F did not frame the scene ({st['camera']})"
    # the bound is editable in the View panel
    app.click(*centre(st["ui_rects"]["section:Solver"]))          # fold the long Solver section
    st = app.wait(lambda s: "section:View" in s["ui_rects"] and s["ui_rects"]["section:View"][3] < 780, 10,
                  "the View header on screen")
    app.click(*centre(st["ui_rects"]["section:View"]))
    st = app.wait(lambda s: "bound:max" in s["ui_rects"], 10, "the bound fields")
    for _ in range(10):                                           # scroll the panel to them
        if st["ui_rects"]["bound:max"][3] < 780:
            break
        app.xdo("mousemove", 150, 600, "click", "5", "click", "5")
        st = app.settle()
    x0, y0, x1, y1 = st["ui_rects"]["bound:max"]
    app.click(int(x0 + 20), int((y0 + y1) / 2))                   # the max x field
    app.settle()
    app.key("ctrl+a")
    app.xdo("type", "60")
    app.key("Return")
    st = app.wait(lambda s: s["bound"]["hi"][0] == pytest.approx(60.0), 10, "the edited bound")
    assert st["bound"]["hi"][1] == pytest.approx(hi[1]) and not st["gl_errors"]
