"""View section: the overlays, the stats window switch, fit."""
from __future__ import annotations

from imgui_bundle import imgui

from .base import Section, record, wrapped
from .number_typing import typed
from .style import DIM, ENTER, RED

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
        imgui.same_line()
        ch, on = imgui.checkbox("follow selected (L)", app.editor.follow is not None)
        if ch and on != (app.editor.follow is not None):
            app.editor.toggle_follow()
        self.trails(app)
        self.bound(app)
        imgui.text_colored(DIM, "Pan: right/middle drag.  Zoom: wheel.  Undo: Ctrl+Z, redo: Ctrl+Shift+Z.")

    def trails(self, app):
        """Tracers (tracer tool, or right-click a body): how long a trail is kept; clear them."""
        tr = app.editor.tracers
        imgui.separator_text("tracers")
        ch, v = imgui.input_float("trail seconds", tr.seconds, 0.5, 2.0, "%.1f", ENTER)
        ch = typed(app, "trail seconds", ch)
        record(app, "view:trail_seconds")
        if ch:
            try:
                tr.set_seconds(v)
                self.error = ""
            except ValueError as exc:
                self.error = str(exc)
                app.notices.notify(f"refused: {exc}", error=True)
        imgui.same_line()
        if imgui.button(f"remove all ({len(tr.items)})"):
            tr.items = []

    def bound(self, app):
        """The world bound: shown, editable; bodies that cross it are removed (undoable)."""
        b = app.bound
        imgui.separator_text("world bound")
        _, b.shown = imgui.checkbox("show it", b.shown)
        imgui.same_line()
        _, b.enabled = imgui.checkbox("remove bodies that leave it", b.enabled)
        ch1, lo = imgui.input_float2("bound min (m)", [float(v) for v in b.lo], "%.1f", ENTER)
        ch1 = typed(app, "bound min", ch1)
        record(app, "bound:min")
        ch2, hi = imgui.input_float2("bound max (m)", [float(v) for v in b.hi], "%.1f", ENTER)
        ch2 = typed(app, "bound max", ch2)
        record(app, "bound:max")
        if ch1 or ch2:
            try:
                b.set(lo, hi)
                self.error = ""
                app.notices.notify(f"world bound: {b.describe()}")
            except ValueError as exc:
                self.error = str(exc)
                app.notices.notify(f"refused: {exc}", error=True)
        if imgui.button("Bound from the scene"):
            b.fit_scene(app.world.render_data())
        if getattr(self, "error", ""):
            wrapped(RED, self.error)
