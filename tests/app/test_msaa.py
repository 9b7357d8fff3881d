"""Issue 16, "smooth (multisampled) edges": the window asks for 4x multisampling and falls back to
the plain config when the driver refuses; either way it opens and draws, the log and the status
say which config is in use, and the multisampled one really smooths a slanted edge."""
from __future__ import annotations

import json

import numpy as np
import pytest

from test_tools import to_screen

pytestmark = pytest.mark.app


def slanted_scene(path):
    """A static slab and a big box turned 0.4 rad (its edges are slanted: aliased without MSAA)."""
    data = {"format": "stelkropp.scene", "version": 2, "name": "slanted",
            "camera": {"center": [0.0, 2.0], "zoom": 40.0},
            "bodies": [{"name": "ground", "kind": "static", "shape": {"box": [16, 1]}, "position": [0, -0.5]},
                       {"name": "tilted", "kind": "static", "shape": {"box": [4, 4]}, "position": [0, 3.0],
                        "angle": 0.4}]}
    path.write_text(json.dumps(data))
    return path


def box_centre(st):
    return tuple(map(int, to_screen(st, [0.0, 3.0])))


def run(launch, tmp_path, name, env):
    app = launch(slanted_scene(tmp_path / f"{name}.json"), "--paused", "--no-stats", env=env, subdir=name)
    st = app.wait_ready(10)
    img = app.screenshot(name)
    return app, st, img


def test_software_gl_is_plain_by_default(launch, tmp_path):
    """llvmpipe shades every sample on the CPU: by default the sandbox does not multisample there."""
    app, st, img = run(launch, tmp_path, "default", {})
    cfg = st["gl_config"]
    assert cfg["msaa"] is False and cfg["samples"] == 0 and cfg["samples_requested"] == 0, cfg
    assert "software renderer (llvmpipe" in cfg["fallback"], cfg
    assert "multisampling off (STELKROPP_MSAA_SAMPLES=4 turns it on)" in app.logtext()
    cx, cy = box_centre(st)
    centre = img[cy - 5:cy + 5, cx - 5:cx + 5].reshape(-1, 3).mean(axis=0)
    assert abs(centre - np.array([74, 83, 97])).max() < 20, f"the scene is not drawn: {centre}"


def test_multisampled_when_asked(launch, tmp_path):
    app, st, img = run(launch, tmp_path, "msaa", {"STELKROPP_MSAA_SAMPLES": "4"})
    cfg = st["gl_config"]
    # measured here: Xvfb + Mesa llvmpipe offer a 4-sample GLX visual (screen.get_best_config)
    assert cfg["msaa"] and cfg["samples_requested"] == 4, f"4x multisampling refused: {cfg}"
    assert cfg["samples"] == 4 and cfg["fallback"] is None, cfg
    assert "stelkropp: GL config: 4x multisampling" in app.logtext()
    app.close()
    # the same scene on the plain config: the flat fills are the same colours, the edges differ
    # (the multisampled framebuffer resolves partial coverage into blends)
    plain_app, pst, pimg = run(launch, tmp_path, "plain", {"STELKROPP_MSAA_SAMPLES": "0"})
    assert pst["gl_config"]["msaa"] is False and pst["gl_config"]["samples"] == 0
    assert pst["camera"] == st["camera"]
    diff = np.abs(img - pimg).max(axis=2)
    cx, cy = box_centre(st)
    assert diff[cy - 20:cy + 20, cx - 20:cx + 20].max() <= 3, "the fills differ: not the same scene"
    changed = int(np.count_nonzero(diff[:, 360:] > 8))
    assert changed > 1000, f"multisampling changed only {changed} edge pixels"
    assert not st["gl_errors"] and not pst["gl_errors"]


def test_refused_config_falls_back_to_plain(launch, tmp_path):
    app, st, img = run(launch, tmp_path, "refused", {"STELKROPP_MSAA_SAMPLES": "1024"})
    cfg = st["gl_config"]
    assert cfg["msaa"] is False and cfg["samples_requested"] == 1024 and cfg["samples"] == 0, cfg
    assert "NoSuchConfigException" in cfg["fallback"], cfg
    assert "1024x multisampling refused" in app.logtext() and "plain config" in app.logtext()
    # the window opened and draws the scene: the tilted box's fill at its centre
    cx, cy = box_centre(st)
    centre = img[cy - 5:cy + 5, cx - 5:cx + 5].reshape(-1, 3).mean(axis=0)
    assert abs(centre - np.array([74, 83, 97])).max() < 20, f"the scene is not drawn: {centre}"
    assert st["frame"] > 10 and not st["gl_errors"]
