"""Issue 16, item 9: the stats plots are readable: they fill a resizable window, y tick labels are
spaced so they cannot overlap, there is a time axis, the legend is outside the curves, and the
pointer over a plot reads out every series."""
from __future__ import annotations

import numpy as np
import pytest

from sandbox_pixels import ROOT

pytestmark = pytest.mark.app


def plot(st, title):
    return next(p for p in st["plots"] if p["title"] == title)


def test_plots_resize_have_spaced_ticks_and_a_hover_readout(launch):
    app = launch(ROOT / "scenes" / "pyramid.json")
    st = app.wait_ready(60)
    for p in st["plots"]:
        assert p["tick_px"] >= 26, f"{p['title']}: y ticks {p['tick_px']:.0f} px apart overlap"
        x0, y0, x1, y1 = p["rect"]
        assert y1 - y0 >= 90 and x1 - x0 >= 90, f"{p['title']} is too small to read: {p['rect']}"
    # the time axis: its label and tick numbers are drawn under each plot area
    img = app.screenshot("plots")
    x0, y0, x1, y1 = map(int, plot(st, "energy (J)")["rect"])
    under = img[y1 + 2:y1 + 34, x0:x1]
    assert int(np.count_nonzero(under.min(axis=2) > 150)) > 80, "no time axis under the energy plot"
    # the legend sits outside the plot area: no legend box inside the curves' rectangle
    # (its entries are drawn above it: bright text between the title and the plot area)
    above = img[max(0, y0 - 26):y0 - 2, x0:x1]
    assert int(np.count_nonzero(above.min(axis=2) > 150)) > 40, "the energy legend is not above the curves"
    # hover: a readout of every series at the pointer's time
    app.xdo("mousemove", (x0 + x1) // 2, (y0 + y1) // 2)
    st = app.wait(lambda s: plot(s, "energy (J)").get("hover"), 10, "the hover readout")
    hover = plot(st, "energy (J)")["hover"]
    assert set(hover["values"]) == {"KE", "PE", "total"} and hover["t"] < 0
    assert hover["values"]["total"] == pytest.approx(hover["values"]["KE"] + hover["values"]["PE"], rel=1e-6, abs=1e-6)
    # resizable: drag the stats window's top edge up; the plots grow with it
    wx0, wy0, wx1, wy1 = st["ui_rects"]["stats_window"]
    h0 = plot(st, "energy (J)")["rect"][3] - plot(st, "energy (J)")["rect"][1]
    app.drag(((wx0 + wx1) / 2, wy0 + 1), ((wx0 + wx1) / 2, wy0 - 200), steps=10)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: s["ui_rects"]["stats_window"][1] < wy0 - 100, 10, "the taller stats window")
    st = app.settle()
    grown = [p["rect"][3] - p["rect"][1] for p in st["plots"]]
    assert max(grown) > h0 + 60 or len({round(p["rect"][1]) for p in st["plots"]}) > 1, (h0, grown)
    for p in st["plots"]:
        assert p["tick_px"] >= 26
    assert not st["gl_errors"]


def label_runs(row_mask):
    """Column runs of lit pixels, joined across gaps < 5 px (the space between a label's glyphs)."""
    cols = np.flatnonzero(row_mask)
    runs = []
    for c in cols:
        if runs and c - runs[-1][1] < 5:
            runs[-1][1] = c
        else:
            runs.append([c, c])
    return runs


def test_time_axis_labels_keep_apart(launch):
    """Item 9: the time axis' tick labels are on a 1-2-5 step and keep >= 10 px apart, in the
    status (positions in the drawn plot area, widths from imgui) and on the screen."""
    app = launch(ROOT / "scenes" / "pyramid.json")
    st = app.wait_ready(60)
    st = app.wait(lambda s: all(p.get("x_ticks", {}).get("t0", 0) < -2 for p in s["plots"]), 60, "2 s of samples")
    img = app.screenshot("time_axis")
    for p in st["plots"]:
        xt, (x0, y0, x1, y1) = p["x_ticks"], p["rect"]
        assert len(xt["values"]) >= 2, f"{p['title']}: fewer than two time ticks: {xt}"
        m = xt["step"] / 10 ** np.floor(np.log10(xt["step"]) + 1e-9)
        assert round(m, 6) in (1, 2, 5), xt["step"]
        xs = [x0 + (v - xt["t0"]) / (xt["t1"] - xt["t0"]) * (x1 - x0) for v in xt["values"]]
        gaps = [(xs[i + 1] - xt["widths"][i + 1] / 2) - (xs[i] + xt["widths"][i] / 2) for i in range(len(xs) - 1)]
        assert min(gaps) >= 9.5, f"{p['title']}: time labels {min(gaps):.1f} px apart: {xt['labels']}"
        # on the screen: the labels' row under the plot area, one run of lit pixels per label
        # (those inside the plot's x range), each run >= 8 px from the next
        strip = img[int(y1) + 6:int(y1) + 18, int(x0) - 12:int(x1) + 12]
        runs = label_runs(strip.min(axis=2).max(axis=0) > 150)
        assert len(runs) >= len(xt["values"]) - 1, f"{p['title']}: {len(runs)} label runs for {xt['labels']}"
        assert all(b[0] - a[1] >= 8 for a, b in zip(runs, runs[1:])), f"{p['title']}: crowded {runs}"
    assert not st["gl_errors"]
