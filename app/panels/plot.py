"""One readable time plot (implot): a labelled time axis whose tick labels keep 10 px apart
(ticks.spaced_ticks), y ticks spaced so their labels never overlap, the legend outside the
curves, and a readout of every series under the pointer."""
from __future__ import annotations

import math

import numpy as np
from imgui_bundle import imgui, implot

from .ticks import spaced_ticks

TICK_PX = 28.0      # at least this many pixels between y tick labels (the font is 13 px high)
MIN_PLOT_H = 150.0   # rows of plots are at least this high (px)
MIN_PLOT_W = 170.0
MAX_POINTS = 120    # points per line: llvmpipe pays for every plotted segment
Y_AXIS_PX = 70.0    # the frame's width minus its plot area's, until a frame has measured it


def nice_ticks(lo: float, hi: float, max_ticks: int) -> np.ndarray:
    """Tick values 1, 2 or 5 x 10^k apart covering [lo, hi], at most ``max_ticks`` of them (>= 2)."""
    if not (math.isfinite(lo) and math.isfinite(hi)):
        lo, hi = 0.0, 1.0
    if hi - lo < 1e-12 * max(1.0, abs(hi)):
        pad = max(abs(hi) * 0.1, 1e-3)
        lo, hi = lo - pad, hi + pad
    max_ticks = max(2, max_ticks)
    raw = (hi - lo) / (max_ticks - 1)
    mag = 10.0 ** math.floor(math.log10(raw))
    for m in (1.0, 2.0, 5.0, 10.0, 20.0):
        step = m * mag
        t0, t1 = math.floor(lo / step) * step, math.ceil(hi / step) * step
        if round((t1 - t0) / step) + 1 <= max_ticks:
            break
    n = int(round((t1 - t0) / step)) + 1
    return t0 + step * np.arange(n)


def readout(t, series, x):
    """The sample nearest time ``x``: (its time, {label: value})."""
    i = int(np.clip(np.searchsorted(t, x), 0, len(t) - 1))
    if i > 0 and abs(t[i - 1] - x) < abs(t[i] - x):
        i -= 1
    return float(t[i]), {label: float(np.asarray(y)[i]) for label, y in series}


def grid(n, width, height):
    """(columns, rows) for ``n`` plots in a width x height area: as many rows as fit at
    MIN_PLOT_H, the fewest columns that hold them all."""
    rows = max(1, min(n, int(height // MIN_PLOT_H)))
    cols = math.ceil(n / rows)
    while cols > 1 and width / cols < MIN_PLOT_W and rows < n:
        rows += 1
        cols = math.ceil(n / rows)
    return cols, math.ceil(n / cols)


class TimePlot:
    """Draws one plot; ``last`` describes it after drawing (for the status file and tests):
    frame rectangle, number of y ticks and their spacing in pixels, hover readout."""

    def __init__(self, title, unit, key="stats"):
        self.title = title
        self.unit = unit
        self.key = key          # imgui id suffix: plots of the same title in other windows differ
        self.always_legend = False   # a legend even for one series (its name is not the title)
        self.last: dict = {}
        self.inset = Y_AXIS_PX  # frame width minus plot-area width, as the last frame measured it

    def draw(self, t, series, width, height, colors=None):
        """``t``: sample times (s, the newest 0); ``series``: [(label, values)] (NaN: no value
        then); ``colors``: one RGBA per series, or None for implot's own."""
        flags = (implot.Flags_.no_mouse_text | implot.Flags_.no_menus | implot.Flags_.no_box_select).value
        legend = len(series) > 1 or self.always_legend
        if not legend:
            flags |= implot.Flags_.no_legend.value
        ys = [np.asarray(y, dtype=np.float64) for _, y in series]
        finite = [y[np.isfinite(y)] for y in ys]
        finite = [y for y in finite if len(y)] or [np.zeros(1)]
        lo, hi = min(float(y.min()) for y in finite), max(float(y.max()) for y in finite)
        area_h = max(20.0, height - 46.0)          # the frame minus the title and the time axis
        ticks = nice_ticks(lo, hi, int(area_h // TICK_PX) + 1)
        self.last = {"title": self.title, "ticks": len(ticks), "tick_px": area_h / max(1, len(ticks) - 1)}
        if not implot.begin_plot(f"{self.title}##{self.key}", imgui.ImVec2(width, height), flags):
            return
        implot.setup_axes("time (s)", "", 0, 0)
        implot.setup_axis_limits(implot.ImAxis_.x1.value, float(t[0]), 0.0, implot.Cond_.always.value)
        self.time_ticks(float(t[0]), 0.0, width)
        implot.setup_axis_limits(implot.ImAxis_.y1.value, float(ticks[0]), float(ticks[-1]), implot.Cond_.always.value)
        implot.setup_axis_ticks(implot.ImAxis_.y1.value, [float(v) for v in ticks])
        implot.setup_axis_format(implot.ImAxis_.y1.value, "%.3g")
        if legend:
            implot.setup_legend(implot.Location_.north.value,
                                (implot.LegendFlags_.outside | implot.LegendFlags_.horizontal).value)
        k = max(1, len(t) // MAX_POINTS)
        tx = np.ascontiguousarray(t[::k], dtype=np.float64)
        for i, ((label, _), y) in enumerate(zip(series, ys)):
            spec = implot.Spec()
            if colors is not None:
                spec.line_color = imgui.ImVec4(*colors[i])
            implot.plot_line(label, tx, np.ascontiguousarray(y[::k]), spec=spec)
        pos, size = implot.get_plot_pos(), implot.get_plot_size()
        self.last["rect"] = (pos.x, pos.y, pos.x + size.x, pos.y + size.y)
        self.inset = width - size.x
        if implot.is_plot_hovered():
            self.hover(t, series)
        implot.end_plot()

    def time_ticks(self, t0, t1, width):
        """The time axis' ticks: the finest 1-2-5 step whose labels keep 10 px apart in the plot
        area (as wide as the frame minus the last measured y-axis inset)."""
        area_w = max(1.0, width - self.inset)
        values, labels, step = spaced_ticks(t0, t1, area_w, lambda s: imgui.calc_text_size(s).x)
        if values:
            implot.setup_axis_ticks(implot.ImAxis_.x1.value, values, labels)
        widths = [imgui.calc_text_size(s).x for s in labels]
        self.last["x_ticks"] = {"values": values, "labels": labels, "widths": widths, "step": step,
                                "t0": t0, "t1": t1}

    def hover(self, t, series):
        """A vertical line at the pointer's time and a tooltip with every series' value there."""
        x = implot.get_plot_mouse_pos().x
        when, values = readout(t, series, x)
        implot.plot_inf_lines("##cursor", np.array([when]))
        imgui.begin_tooltip()
        imgui.text(f"{-when:.2f} s ago")
        for label, v in values.items():
            imgui.text(f"{label}: {v:.4g} {self.unit}")
        imgui.end_tooltip()
        self.last["hover"] = {"t": when, "values": values}
