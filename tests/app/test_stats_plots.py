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
