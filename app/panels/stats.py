"""The stats window: frame-time split, counts, and implot plots of the sampled series."""
from __future__ import annotations

import numpy as np
from imgui_bundle import imgui, implot

from .base import record_window
from .style import DIM, STATS_W


def plot(title, t, series, size):
    """One implot line plot of ``series`` [(label, y)] over times ``t`` (s, ending at 0)."""
    flags = (implot.Flags_.no_mouse_text | implot.Flags_.no_menus | implot.Flags_.no_box_select).value
    if len(series) == 1:
        flags |= implot.Flags_.no_legend.value
    if implot.begin_plot(title, size, flags):
        implot.setup_axes("", "", implot.AxisFlags_.no_tick_labels.value,
                          implot.AxisFlags_.auto_fit.value)
        implot.setup_axis_limits(implot.ImAxis_.x1.value, float(t[0]), 0.0, implot.Cond_.always.value)
        if len(series) > 1:
            implot.setup_legend(implot.Location_.north_east.value, implot.LegendFlags_.horizontal.value)
        # at most ~120 points per line: llvmpipe pays for every plotted segment
        k = max(1, len(t) // 120)
        for label, y in series:
            implot.plot_line(label, np.ascontiguousarray(t[::k], dtype=np.float64),
                             np.ascontiguousarray(np.asarray(y)[::k], dtype=np.float64))
        implot.end_plot()


class StatsWindow:
    def __init__(self, app):
        self.app = app

    def draw(self):
        app = self.app
        io = imgui.get_io()
        W = io.display_size.x
        imgui.set_next_window_pos(imgui.ImVec2(W - 8, 8), imgui.Cond_.first_use_ever.value, imgui.ImVec2(1, 0))
        imgui.set_next_window_size(imgui.ImVec2(STATS_W, 490), imgui.Cond_.first_use_ever.value)
        imgui.set_next_window_bg_alpha(0.82)
        expanded, _ = imgui.begin("Stats###stats", None)
        if expanded:
            self.contents()
        record_window(app, "stats_window")
        imgui.end()

    def contents(self):
        app = self.app
        ft = app.times.avg
        imgui.text(f"{app.times.fps:5.1f} fps   frame {ft['frame']:.2f} ms")
        imgui.text_colored(DIM, f"physics {ft['physics']:.2f}  upload {ft['upload']:.2f}  "
                                f"draw {ft['draw']:.2f}  ui {ft['ui']:.2f} ms")
        info = app.sampler.info
        imgui.text_colored(DIM, f"bodies {info.get('bodies', 0)}  awake {info.get('awake', 0)}  "
                                f"springs {info.get('springs', 0)}  pairs {info.get('contacts', 0)}")
        s = app.sampler.stats
        t, n = s.arrays()
        if n > 1:
            t = t - t[-1]
            size = imgui.ImVec2(-1, 72)
            plot("step time (ms)", t, [("step", s.get("step_ms"))], size)
            plot("energy (J)", t, [("kinetic", s.get("ke")), ("potential", s.get("pe")),
                                   ("total", s.get("ke") + s.get("pe"))], size)
            plot("momentum (kg m/s)", t, [("|p|", s.get("p"))], size)
            plot("max penetration (m)", t, [("depth", s.get("pen"))], size)
            plot("contacts", t, [("contacts", s.get("contacts"))], size)
