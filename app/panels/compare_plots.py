"""The comparison's plots (in the stats window while comparing): every lane's step time, energy
drift, deepest penetration and drift from the main world, one line per lane in its colour."""
from __future__ import annotations

from imgui_bundle import imgui

from ..compare import LANE_COLORS
from .plot import TimePlot, grid

#: (title, unit, LaneStats key, whether the main world has a line of its own)
PLOTS = (("step time (ms)", "ms", "step_ms", True), ("energy drift (J)", "J", "energy", True),
         ("max penetration (m)", "m", "pen", True), ("drift from main (m)", "m", "drift", False))


class ComparePlots:
    def __init__(self, app):
        self.app = app
        self.plots = [TimePlot(title, unit, "compare") for title, unit, _, _ in PLOTS]

    def draw(self):
        cmp = self.app.compare
        main = cmp.main
        n = min([main.n] + [ln.stats.n for ln in cmp.lanes])
        if n < 2:
            imgui.text("waiting for the rivals' first steps ...")
            return
        t = main.get("t")[-n:]
        t = t - t[-1]
        names = unique([self.app.world.solver] + [ln.label for ln in cmp.lanes])
        avail = imgui.get_content_region_avail()
        cols, rows = grid(len(self.plots), avail.x, avail.y)
        sp = imgui.get_style().item_spacing
        w = (avail.x - (cols - 1) * sp.x) / cols
        h = max(60.0, (avail.y - (rows - 1) * sp.y) / rows)
        for i, (plot, (_, _, key, with_main)) in enumerate(zip(self.plots, PLOTS)):
            if i % cols:
                imgui.same_line()
            series, colors = [], []
            if with_main:
                series.append((names[0], main.get(key)[-n:]))
                colors.append(LANE_COLORS[0])
            for name, ln in zip(names[1:], cmp.lanes):
                series.append((name, ln.stats.get(key)[-n:]))
                colors.append(ln.color)
            plot.draw(t, series, w, h, colors)


def unique(labels):
    """Labels made unique for implot (a repeated label would merge two lines into one entry)."""
    out, seen = [], {}
    for s in labels:
        seen[s] = seen.get(s, 0) + 1
        out.append(s if seen[s] == 1 else f"{s} ({seen[s]})")
    return out
