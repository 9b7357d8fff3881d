"""The stats window: frame-time split, counts, and time plots of the sampled series laid out in
a grid that fills the window (drag its edges to resize it)."""
from __future__ import annotations

from imgui_bundle import imgui

from .base import record, record_window
from .compare_plots import ComparePlots
from .contact_readout import ContactReadout
from .plot import TimePlot, grid
from .style import DIM, PANEL_W, STATS_H


def stats_default_rect(width, height):
    """The stats window's first place: a strip along the bottom, right of the side panel, so
    the scene keeps a wide free area above it (x0, y0, x1, y1; y down)."""
    return (PANEL_W + 16.0, height - 8.0 - STATS_H, width - 8.0, height - 8.0)


COUNTS_HELP = ("The core tests no pair of two sleeping bodies (nor a sleeping body against a static one),\n"
              "so contacts between sleeping bodies are not counted.\n"
              "touching: world.contacts(); pairs tested: the narrow phase's pairs (world.info()['contacts']),\n"
              "touching or a speculative margin apart.")


def counts_text(c):
    """The counts line for ``StatsSampler.counts()``."""
    text = (f"bodies {c['bodies']}  awake {c['awake']}  asleep {c['asleep']}  springs {c['springs']}   "
            f"awake contacts: {c['touching']} touching, {c['pairs']} pairs tested")
    return text + ("  (all asleep: the last step's)" if c["all_asleep"] else "")


class StatsWindow:
    """``plots`` hold what each drew last (rectangles, ticks, hover readout) for the status file."""

    SERIES = (("step time (ms)", "ms", (("step", "step_ms"),)),
              ("energy (J)", "J", (("KE", "ke"), ("PE", "pe"), ("total", None))),
              ("momentum (kg m/s)", "kg m/s", (("|p|", "p"),)),
              ("max penetration (m)", "m", (("depth", "pen"),)),
              ("awake contacts", "", (("touching", "contacts"),)))

    def __init__(self, app):
        self.app = app
        self.plots = [TimePlot(title, unit) for title, unit, _ in self.SERIES]
        self.compare = ComparePlots(app)
        self.contacts = ContactReadout(app)   # the selected body's contacts: impulses, hits per second
        self.show_compare = False      # the next frame selects the Compare tab (set on start)
        self.show_plot = False         # the next frame selects the Plot tab (a first series chosen)
        self.tab = "Stats"             # the tab drawn last

    def draw(self):
        app = self.app
        io = imgui.get_io()
        x0, y0, x1, y1 = stats_default_rect(io.display_size.x, io.display_size.y)
        imgui.set_next_window_pos(imgui.ImVec2(x0, y0), imgui.Cond_.first_use_ever.value)
        imgui.set_next_window_size(imgui.ImVec2(x1 - x0, y1 - y0), imgui.Cond_.first_use_ever.value)
        imgui.set_next_window_size_constraints(imgui.ImVec2(260, 160), imgui.ImVec2(1e5, 1e5))
        imgui.set_next_window_bg_alpha(0.82)
        expanded, _ = imgui.begin("Stats###stats", None)
        if expanded and (app.compare.active or app.recorder.series):
            self.tabs()
        elif expanded:
            self.contents()
        record_window(app, "stats_window")
        imgui.end()

    def tabs(self):
        """Stats, and Plot (while quantities are plotted) and Compare (while comparing) tabs;
        a tab is selected when its first series or the comparison starts."""
        if not imgui.begin_tab_bar("stats_tabs"):
            return
        app = self.app
        tabs = [("Stats", self.contents, False)]
        if app.recorder.series:
            tabs.append(("Plot", app.panels.plot.contents, self.show_plot))
        if app.compare.active:
            tabs.append(("Compare", self.compare.draw, self.show_compare))
        self.show_plot = self.show_compare = False
        for name, draw, select in tabs:
            flags = imgui.TabItemFlags_.set_selected.value if select else 0
            opened = imgui.begin_tab_item(f"{name}###tab{name}", None, flags)[0]
            record(app, f"tab:{name}")
            if opened:
                self.tab = name
                draw()
                imgui.end_tab_item()
        imgui.end_tab_bar()

    def counts(self):
        """The body and contact counts on a line of their own, saying that the contacts are
        those of awake bodies (a pile of sleeping boxes has none); hovered, why."""
        c = self.app.sampler.counts()
        text = counts_text(c)
        imgui.text_colored(DIM, text)
        record(self.app, "stats:counts")
        if imgui.is_item_hovered():
            imgui.set_tooltip(COUNTS_HELP)
        self.app.ui_values["stats:counts"] = dict(c, text=text)

    def contents(self):
        app = self.app
        ft = app.times.avg
        imgui.text(f"{app.times.fps:5.1f} fps   frame {ft['frame']:.2f} ms")
        imgui.same_line()
        imgui.text_colored(DIM, f"  physics {ft['physics']:.2f}  upload {ft['upload']:.2f}  "
                                f"draw {ft['draw']:.2f}  ui {ft['ui']:.2f} ms")
        self.counts()
        self.contacts.draw()
        s = app.sampler.stats
        t, n = s.arrays()
        if n < 2:
            return
        t = t - t[-1]
        avail = imgui.get_content_region_avail()
        cols, rows = grid(len(self.plots), avail.x, avail.y)
        sp = imgui.get_style().item_spacing
        w = (avail.x - (cols - 1) * sp.x) / cols
        h = max(60.0, (avail.y - (rows - 1) * sp.y) / rows)
        for i, (plot, (_, _, keys)) in enumerate(zip(self.plots, self.SERIES)):
            if i % cols:
                imgui.same_line()
            series = [(label, s.get(k) if k else s.get("ke") + s.get("pe")) for label, k in keys]
            plot.draw(t, series, w, h)
