"""Issue 16, "plot anything": tick quantities of the selected body or spring in the inspector and
they are plotted live in the stats window's Plot tab (one plot per unit, several series each),
exported as CSV, in a window that can be resized; a reset keeps what is plotted."""
from __future__ import annotations

import csv
import math

import numpy as np
import pytest

from test_compare import centre
from test_tools import body, to_screen, tools_scene

pytestmark = pytest.mark.app


def series(st, label):
    return next(s for s in st["plot"]["series"] if s["label"] == label)


def tick(app, st, *quantities):
    """Tick ``quantities`` in the inspector's plot row."""
    for q in quantities:
        app.click(*centre(st["ui_rects"][f"plot:q:{q}"]))
        st = app.settle()
    return st


def tension(c, k=80.0, damping=1.0, rest=1.5, anchor_b=(0.0, 5.5)):
    """The spring "hang" of tools_scene: anchor (0, 0.5) on box c (centred, so its centre of mass
    is its position), world anchor (0, 5.5): k (L - L0) + c dL/dt, computed here from c's state."""
    a = c["angle"]
    r = np.array([-math.sin(a) * 0.5, math.cos(a) * 0.5])
    pa = np.array(c["position"]) + r
    d = pa - np.array(anchor_b)
    length = float(np.hypot(*d))
    v = np.array(c["velocity"]) + c["angular_velocity"] * np.array([-r[1], r[0]])
    return k * (length - rest) + damping * float(np.dot(v, d / length))


def coloured(img, rect) -> int:
    """Saturated pixels (plot lines) in a rectangle."""
    x0, y0, x1, y1 = map(int, rect)
    a = img[y0:y1, x0:x1]
    return int(np.count_nonzero(a.max(axis=2) - a.min(axis=2) > 60))


@pytest.mark.slow
def test_plot_quantities_of_a_body_and_a_spring(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")     # paused: c stays put to be clicked
    st = app.wait_ready(10)
    c = body(st, "c")
    app.click(*map(int, c["screen"]))
    st = app.wait(lambda s: s["selection"] == [c["id"]], 10, "box c selected")
    st = app.settle()
    st = tick(app, st, "y", "x", "speed")
    st = app.wait(lambda s: len(s["plot"]["series"]) == 3 and s["plot"]["open"], 10, "three series")
    # the spring: click its coil between the world anchor and box c
    app.click(*map(int, to_screen(st, (0.0, 5.3))))
    st = app.wait(lambda s: s["selection"] and s["selection"][0] != c["id"], 10, "the spring selected")
    st = app.settle()
    st = tick(app, st, "force")
    st = app.wait(lambda s: len(s["plot"]["series"]) == 4, 10, "four series")
    assert all(s["n"] <= 1 for s in st["plot"]["series"]), "samples recorded while paused (one: the start)"
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    st = app.wait(lambda s: len(s["plot"]["series"]) == 4 and series(s, "hang: force")["n"] > 40,
                  30, "the spring force series")
    assert [s["unit"] for s in st["plot"]["series"]] == ["m", "m", "m/s", "N"]
    # one plot per unit, the two lengths (x, y) in one plot
    plots = st["plot"]["plots"]
    assert sorted(p["title"] for p in plots) == ["N", "m", "m/s"]
    img = app.screenshot("plots")
    for p in plots:
        assert coloured(img, p["rect"]) > 30, f"no curve drawn in the {p['title']} plot"
    # paused, the last samples are the state the status reports
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    st = app.wait(lambda s: not s["running"], 10, "paused")
    st = app.settle()
    c = body(st, "c")
    assert series(st, "c: y")["last"] == pytest.approx(c["position"][1], abs=1e-9)
    assert series(st, "c: x")["last"] == pytest.approx(c["position"][0], abs=1e-9)
    assert series(st, "c: speed")["last"] == pytest.approx(math.hypot(*c["velocity"]), abs=1e-9)
    assert series(st, "hang: force")["last"] == pytest.approx(tension(c), rel=1e-6, abs=1e-6)
    # CSV export: a time column and one per series, every recorded sample
    app.click(*centre(st["ui_rects"]["plot:export"]))
    st = app.wait(lambda s: s["plot"]["csv"], 10, "the CSV export")
    with open(st["plot"]["csv"]) as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["time (s)", "c: y (m)", "c: x (m)", "c: speed (m/s)", "hang: force (N)"]
    assert len(rows) - 1 == series(st, "c: y")["n"]
    times = [float(r[0]) for r in rows[1:]]
    assert all(b > a for a, b in zip(times, times[1:])), "CSV times are not increasing"
    assert float(rows[-1][1]) == pytest.approx(c["position"][1], abs=1e-9)
    assert float(rows[-1][4]) == pytest.approx(tension(c), rel=1e-6, abs=1e-6)
    # resizable: drag the stats window's top edge up; the plots grow with it
    wx0, wy0, wx1, wy1 = st["ui_rects"]["stats_window"]
    h0 = max(p["rect"][3] - p["rect"][1] for p in st["plot"]["plots"])
    app.drag(((wx0 + wx1) / 2, wy0 + 1), ((wx0 + wx1) / 2, wy0 - 200), steps=10)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: s["ui_rects"]["stats_window"][1] < wy0 - 100, 10, "the taller stats window")
    st = app.settle()
    h1 = max(p["rect"][3] - p["rect"][1] for p in st["plot"]["plots"])
    rows = len({round(p["rect"][1]) for p in st["plot"]["plots"]})
    assert h1 > h0 + 60 or rows > 1, (h0, h1, rows)      # taller plots, or a second row of them
    # a reset keeps what is plotted and follows the new world's c
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("r")
    app.key("space")
    st = app.wait(lambda s: s["running"] and s["plot"]["series"] and series(s, "c: y")["n"] > 10, 20,
                  "samples after the reset")
    assert len(st["plot"]["series"]) == 4 and math.isfinite(series(st, "c: y")["last"])
    assert not st["gl_errors"]
