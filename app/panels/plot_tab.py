"""The Plot tab of the stats window: the recorded quantities of bodies and springs (chosen in the
inspector), one plot per unit with several series each, a list to remove series, and CSV export.
The plots fill the stats window, which is resizable (drag an edge or corner)."""
from __future__ import annotations

import time
from pathlib import Path

from imgui_bundle import imgui

from ..probes import quantities_of
from ..scenes import user_scenes_dir
from .base import record
from .plot import TimePlot, grid
from .style import DIM


def export_dir() -> Path:
    """Where CSV exports go: ``plots`` beside the user's scene folder (platformdirs' user data dir)."""
    return user_scenes_dir().parent / "plots"


class PlotTab:
    """``last_csv``: the path of the last export (None before one); ``ms``: the time building
    the tab took this frame (0 when not drawn; the window resets it; the frame benchmark reports it)."""

    def __init__(self, app):
        self.app = app
        self.plots: dict[str, TimePlot] = {}
        self.last_csv = None
        self.ms = 0.0

    @property
    def open(self) -> bool:
        """Is the Plot tab the one shown?"""
        return self.app.panels.show_stats and self.app.panels.stats.tab == "Plot"

    def show(self):
        """Bring the Plot tab forward (the stats window opens if it was closed)."""
        self.app.panels.show_stats = True
        self.app.panels.stats.show_plot = True

    def contents(self):
        t0 = time.perf_counter()
        try:
            self._contents()
        finally:
            self.ms += (time.perf_counter() - t0) * 1e3

    def _contents(self):
        app = self.app
        rec = app.recorder
        if imgui.button("Export CSV"):
            self.export(app)
        record(app, "plot:export")
        imgui.same_line()
        if imgui.button("Clear samples"):
            rec.clear()
        if self.last_csv:
            imgui.same_line()
            imgui.text_colored(DIM, f"-> {self.last_csv.name}")
            if imgui.is_item_hovered():
                imgui.set_tooltip(str(self.last_csv))
        if rec.series and imgui.tree_node(f"series ({len(rec.series)})###series"):
            for s in list(rec.series):
                if imgui.small_button(f"remove##{id(s)}"):
                    rec.remove(s)
                imgui.same_line()
                imgui.text(f"{s.label} ({s.unit})")
            imgui.tree_pop()
        if not rec.series:
            imgui.text_colored(DIM, "Select a body or spring and tick what to plot in the inspector.")
            return
        groups = rec.groups()
        t = rec.times()
        if len(t) < 2:
            imgui.text_colored(DIM, "recording (play the simulation) ...")
            return
        t = t - t[-1]
        avail = imgui.get_content_region_avail()
        cols, rows = grid(len(groups), avail.x, avail.y)
        sp = imgui.get_style().item_spacing
        w = (avail.x - (cols - 1) * sp.x) / cols
        h = max(60.0, (avail.y - (rows - 1) * sp.y) / rows)
        for i, (unit, series) in enumerate(groups.items()):
            if i % cols:
                imgui.same_line()
            plot = self.plots.get(unit)
            if plot is None:
                plot = self.plots[unit] = TimePlot(unit, unit, "plotwin")
                plot.always_legend = True
            plot.draw(t, [(s.label, rec.values(s)) for s in series], w, h)

    def export(self, app):
        stem = app.editor.doc.path.stem if app.editor.doc.path else "untitled"
        path = export_dir() / f"{stem}-{time.strftime('%Y%m%d-%H%M%S')}.csv"
        try:
            self.last_csv = app.recorder.export_csv(path)
            app.notices.notify(f"plot exported: {self.last_csv}")
        except OSError as exc:
            app.notices.notify(f"CSV export failed: {exc}", error=True)

    def describe(self) -> dict:
        """For the status file: the series, their sample counts and last values, the plots."""
        rec = self.app.recorder
        out = []
        for s in rec.series:
            v = rec.values(s)
            out.append({"label": s.label, "unit": s.unit, "quantity": s.quantity, "n": int(len(v)),
                        "last": float(v[-1]) if len(v) else None})
        return {"open": self.open, "series": out, "csv": str(self.last_csv) if self.last_csv else None,
                "plots": [p.last for u, p in self.plots.items() if u in rec.groups()]}


#: short checkbox labels (the full name is the tooltip)
SHORT = {"angular velocity": "ang. vel.", "kinetic energy": "KE", "potential energy": "PE"}


def probe_checkboxes(app, item):
    """The inspector's "plot" row: a checkbox per quantity of ``item`` (short labels, wrapped);
    ticking one brings the Plot tab forward."""
    rec, refs = app.recorder, app.editor.refs
    imgui.text_colored(DIM, "plot:")
    room = imgui.get_content_region_avail().x
    used = imgui.calc_text_size("plot: ").x
    for name in quantities_of(item):
        label = SHORT.get(name, name)
        wdt = imgui.calc_text_size(label).x + imgui.get_frame_height() + 12
        if used + wdt < room:
            imgui.same_line()
        else:
            used = 0.0
        used += wdt
        ch, _ = imgui.checkbox(f"{label}##plot", rec.has(item, name, refs))
        record(app, f"plot:q:{name}")
        if imgui.is_item_hovered():
            imgui.set_tooltip(f"plot {name}")
        if ch and rec.toggle(item, name, refs, app.world):
            app.panels.plot.show()
