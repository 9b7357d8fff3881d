"""View section: the overlays, the stats window switch, fit."""
from __future__ import annotations

from imgui_bundle import imgui

from .base import Section, record
from .style import DIM

OVERLAYS = (("contacts and normals (C)", "contacts"), ("AABBs (B)", "aabbs"), ("quadtree (Q)", "quadtree"),
            ("velocity arrows (V)", "velocities"), ("centres of mass (M)", "com"), ("springs", "springs"))


class ViewSection(Section):
    title = "View"
    default_open = False

    def draw(self):
        app = self.app
        o = app.overlays
        for label, attr in OVERLAYS:
            ch, v = imgui.checkbox(label, getattr(o, attr))
            record(app, f"overlay:{attr}")
            if ch:
                setattr(o, attr, v)
        ch, app.panels.show_stats = imgui.checkbox("stats window", app.panels.show_stats)
        if imgui.button("Fit scene (F)"):
            app.fit()
        imgui.text_colored(DIM, "Pan: right/middle drag.  Zoom: wheel.  Undo: Ctrl+Z, redo: Ctrl+Shift+Z.")
