"""The scene's context menu: a right click (without dragging) on a body offers what can be done
with it there: trace that point, remove its tracers, plot its speed, select it."""
from __future__ import annotations

from imgui_bundle import imgui

from .base import record


class ContextMenu:
    """``open_at(body, point)`` asks for the menu at the pointer; it is drawn the next frame."""

    def __init__(self, app):
        self.app = app
        self.body = None
        self.point = None
        self._pending = False
        self.shown = False

    def open_at(self, body, point):
        self.body, self.point = body, tuple(map(float, point))
        self._pending = True

    def draw(self):
        app, ed = self.app, self.app.editor
        if self._pending:
            imgui.open_popup("scene_context")
            self._pending = False
        self.shown = imgui.begin_popup("scene_context")
        if not self.shown:
            return
        b = self.body
        if b is None or not b.alive:
            imgui.close_current_popup()
            imgui.end_popup()
            return
        imgui.text_disabled(f"body {b.name or b.id}")
        if imgui.menu_item("Trace this point", "", False)[0]:
            ed.tracers.add(b, self.point, ed.refs, ed.world)
            ed.notify(f"tracing a point of {b.name or b.id}")
        record(app, "ctx:trace")
        if imgui.menu_item("Remove its tracers", "", False)[0]:
            ed.tracers.remove_body(b, ed.refs)
        record(app, "ctx:untrace")
        if imgui.menu_item("Plot its speed", "", False)[0]:
            if not app.recorder.has(b, "speed", ed.refs):
                app.recorder.toggle(b, "speed", ed.refs, ed.world)
            app.panels.plot.show()
        record(app, "ctx:plot")
        if imgui.menu_item("Select it", "", False)[0]:
            ed.select(b)
        imgui.end_popup()
