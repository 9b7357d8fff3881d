"""What a scene opens framed on (app/framing.py): its moving bodies down to the ground they will
land on, not the whole long ground, and not only the air they start in (bodies dropped from high
up fell out of the view they opened in); and the caption a scene shows (app/scene_caption.py):
the sentence of its description that says what to try."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import physics
from app.framing import focus_box, ground_below
from app.scene_caption import caption_of

ROOT = Path(__file__).resolve().parent.parent


def test_ground_below_is_the_lowest_top_under_the_box():
    static = np.array([[-50.0, -1.0, 50.0, 0.0],        # the ground, under everything
                       [2.0, 0.0, 4.0, 3.0],            # a block under the box's right part
                       [20.0, 0.0, 22.0, 9.0],          # a tower off to the side
                       [np.nan, np.nan, np.nan, np.nan]])
    assert ground_below(static, np.array([0.0, 10.0]), np.array([3.0, 12.0])) == 0.0   # lowest top under it
    assert ground_below(static, np.array([30.0, 10.0]), np.array([31.0, 12.0])) == 0.0
    assert ground_below(static[1:3], np.array([30.0, 10.0]), np.array([31.0, 12.0])) == 10.0   # none: its own bottom


def test_focus_reaches_down_to_the_ground_and_not_along_it():
    w = physics.World(gravity=(0, -10))
    w.add_body(physics.Polygon.box(200, 1), kind="static", position=(0, -0.5))
    w.add_body(physics.Polygon.box(1, 1), position=(3.0, 20.0))
    lo, hi = focus_box(w)
    assert lo[1] <= 0.0 + 1e-9 and hi[1] >= 20.5, (lo, hi)       # from the landing place to the box
    assert hi[0] - lo[0] < 20.0, (lo, hi)                         # not the 200 m ground


def test_caption_is_the_try_sentence():
    assert caption_of({"description": "A house of cards.  Try pulling one out.  It falls."}) == "Try pulling one out."
    assert caption_of({"description": "Nothing to try here."}) is None
    assert caption_of({}) is None and caption_of({"description": 3}) is None


@pytest.mark.parametrize("name", ["cup", "mass_ratio", "card_house", "joint_grid", "car", "compounds"])
def test_quiet_scenes_say_what_to_try(name):
    # these show nothing happening by themselves (or their point is not visible at a glance)
    meta = json.loads((ROOT / "scenes" / f"{name}.json").read_text())
    caption = caption_of(meta)
    assert caption is not None and len(caption) < 120, caption
