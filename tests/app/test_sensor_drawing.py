"""Issue 15, sensor drawing: a fixture with ``sensor == True`` (the scene's ``"sensor": true``) is
drawn translucent, and lit while something is inside.  Real mouse drag, pixel checks against
the colours of app/render/sensors.py blended over the background."""
from __future__ import annotations

import json

import numpy as np
import pytest

from test_tools import body, to_screen

pytestmark = pytest.mark.app

BG = np.array((0.062, 0.072, 0.098))


def blend(rgba):
    """The colour a fill of ``rgba`` shows over the background (0..255)."""
    return 255 * (np.array(rgba[:3]) * rgba[3] + BG * (1 - rgba[3]))


def patch(img, st, p, r=4):
    x, y = map(int, to_screen(st, p))
    return np.median(img[y - r:y + r + 1, x - r:x + r + 1].reshape(-1, 3), axis=0)


def scene(path):
    data = {"format": "stelkropp.scene", "version": 2, "name": "sensors",
            "camera": {"center": [0.0, 2.0], "zoom": 40.0},
            "bodies": [
                {"name": "ground", "kind": "static", "shape": {"box": [16, 1]}, "position": [0, -0.5]},
                {"name": "sensor_a", "kind": "static", "shape": {"box": [2, 2], "sensor": True}, "position": [-3, 2]},
                {"name": "sensor_b", "kind": "static", "shape": {"box": [2, 2], "sensor": True}, "position": [3, 2]},
                # last: the topmost body, so a click on it picks it rather than the sensor around it
                {"name": "visitor", "kind": "static", "shape": {"box": [0.6, 0.6]}, "position": [-3.4, 2.4]}]}
    path.write_text(json.dumps(data))
    return path


def test_sensors_translucent_and_lit_while_visited(launch, tmp_path):
    from app.render.sensors import LIT_FILL, SENSOR_FILL
    app = launch(scene(tmp_path / "sensors.json"), "--paused")
    st = app.wait_ready(10)
    img = app.screenshot("sensors_start")
    lit, unlit = blend(LIT_FILL), blend(SENSOR_FILL)
    assert patch(img, st, (-2.4, 1.4)) == pytest.approx(lit, abs=12), "sensor_a (visited) is not lit"
    assert patch(img, st, (3.5, 1.5)) == pytest.approx(unlit, abs=12), "sensor_b (empty) is not translucent"
    # a static body outside the sensors keeps its own fill (only sensor fixtures are recoloured)
    assert patch(img, st, (-3.4, 2.4), r=2) == pytest.approx((74, 83, 97), abs=14)
    # drag the visitor (static: the select tool moves it) into sensor_b: a lights, b goes dark
    app.drag(to_screen(st, (-3.4, 2.4)), to_screen(st, (2.6, 2.4)), steps=30)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: body(s, "visitor")["position"][0] > 2.0, 20, "the visitor in sensor_b")
    st = app.settle()
    img = app.screenshot("sensors_moved")
    assert patch(img, st, (-2.4, 1.4)) == pytest.approx(unlit, abs=12), "sensor_a still lit after the visitor left"
    assert patch(img, st, (3.5, 1.5)) == pytest.approx(lit, abs=12), "sensor_b not lit with the visitor inside"
    assert not st["gl_errors"]
