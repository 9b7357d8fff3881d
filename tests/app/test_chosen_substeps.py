"""The solver panel says what soft_step chose for the scene (physics/solvers/soft_step/fit.py): a
scene of 2 mm cards opens with eight sub-steps and a line naming why; typing a value overrides
it (the line goes, no field moves); Defaults hands it back to the scene's choice."""
from __future__ import annotations

import json

import numpy as np
import pytest

from test_mode_switch_pending import centre, visible

pytestmark = pytest.mark.app


def cards_scene(path):
    data = {"format": "stelkropp.scene", "version": 2, "name": "cards",
            "camera": {"center": [0.0, 0.5], "zoom": 120.0},
            "world": {"gravity": [0, -10], "solver": "soft_step", "sleeping": False},
            "bodies": [{"name": "ground", "kind": "static", "shape": {"box": [6, 0.5]}, "position": [0, -0.25]}]
            + [{"name": f"card{i}", "shape": {"box": [0.002, 0.4]}, "position": [0.3 * i - 0.6, 0.2]}
               for i in range(5)]}
    path.write_text(json.dumps(data))
    return path


def dim_text_pixels(img, rect) -> int:
    """Pixels of the panels' dim text (app/panels/style.py: DIM, 158 168 184) in ``rect``."""
    x0, y0, x1, y1 = (int(v) for v in rect)
    a = img[max(0, y0):y1, max(0, x0):x1].astype(int)
    return int(np.count_nonzero((abs(a[..., 0] - 158) < 30) & (abs(a[..., 1] - 168) < 30) & (abs(a[..., 2] - 184) < 30)))


def type_into_slider(app, rect, text):
    """Ctrl+click a slider (ImGui's way to type into one), select its text, type, press Return."""
    x0, y0, x1, y1 = rect
    app.xdo("keydown", "ctrl")
    app.settle()
    app.click(int(x0 + 30), int((y0 + y1) / 2))
    app.settle()
    app.key("a")
    app.settle()
    app.xdo("keyup", "ctrl")
    app.settle()
    app.xdo("type", "--delay", "30", text)
    app.key("Return")


def layout(st):
    """The settings fields' rects relative to the first one (scrolling moves them all)."""
    rects = {k: v for k, v in st["ui_rects"].items() if k.startswith("setting:")}
    x, y = rects["setting:substeps"][:2]
    return {k: (round(r[0] - x), round(r[1] - y), round(r[2] - x), round(r[3] - y)) for k, r in rects.items()}


def test_the_panel_names_the_choice_and_a_typed_value_overrides_it(launch, tmp_path):
    app = launch(cards_scene(tmp_path / "cards.json"), "--paused")
    app.wait_ready()
    st = visible(app, "solver_chosen:substeps")
    assert st["ui_values"]["solver_settings"]["settings"]["substeps"] == 8
    line = st["ui_values"]["solver_chosen"]["substeps"]
    assert line.startswith("8 (thin shapes: body 'card0' is 2 mm thick"), line
    img = app.screenshot("chosen_substeps")        # look at it: the line under the settings
    assert dim_text_pixels(img, st["ui_rects"]["solver_chosen:substeps"]) > 100
    fields = layout(st)

    st = visible(app, "setting:substeps")
    type_into_slider(app, st["ui_rects"]["setting:substeps"], "4")
    st = app.wait(lambda s: s["ui_values"]["solver_settings"]["settings"]["substeps"] == 4, 20, "substeps 4")
    st = app.settle()
    assert st["ui_values"]["solver_chosen"] == {} and "solver_chosen:substeps" not in st["ui_rects"]
    moved = {k for k, r in fields.items() if layout(st).get(k) != r}
    assert not moved, f"fields moved when the line went: {sorted(moved)}"

    st = visible(app, "solver_defaults")
    app.click(*centre(st["ui_rects"]["solver_defaults"]))
    # the fitted value and its line may land in different frames: wait for both (a line that
    # never comes back fails here, after 20 s)
    st = app.wait(lambda s: s["ui_values"]["solver_settings"]["settings"]["substeps"] == 8
                  and "substeps" in s["ui_values"]["solver_chosen"], 20, "back to 8, with its line")
    assert st["ui_values"]["solver_chosen"]["substeps"].startswith("8 (thin shapes")
    assert not st["fault"] and not st["gl_errors"]
