"""Compare section: choose the modes (or settings) to run beside the open scene, start and stop
the comparison, ghost or split view, and each rival's settings, edited live."""
from __future__ import annotations

from imgui_bundle import imgui

from physics import options

from ..compare import LANE_COLORS, MAX_RIVALS
from .base import Section, record, wrapped
from .number_typing import typed
from .solver import setting_widget
from .style import AMBER, DIM, RED

SAME_MODE = "same mode, other settings"


class CompareSection(Section):
    """``chosen``: the rival modes ticked (solver names, or SAME_MODE for a copy of the main
    world's mode whose settings are then edited here)."""
    title = "Compare solvers"
    default_open = False

    def __init__(self, app):
        super().__init__(app)
        self.chosen: list[str] = []
        self.error = ""

    def draw(self):
        app = self.app
        cmp = app.compare
        if not cmp.active:
            self.choose(app)
        else:
            self.running(app, cmp)
        if self.error:
            wrapped(RED, self.error)

    def choose(self, app):
        w = app.world
        wrapped(DIM, f"Run this scene in other modes beside {w.solver}, live:")
        record(app, "compare:help")
        for m in (*[s for s in options.SOLVERS if s != w.solver], SAME_MODE):
            ch, on = imgui.checkbox(f"{m}##cmp", m in self.chosen)
            record(app, f"compare:mode:{m}")
            if ch:
                if on and len(self.chosen) < MAX_RIVALS:
                    self.chosen.append(m)
                elif not on and m in self.chosen:
                    self.chosen.remove(m)
                elif on:
                    self.error = f"at most {MAX_RIVALS} modes at once"
        if imgui.button("Start comparison"):
            self.start(app)
        record(app, "compare:start")

    def start(self, app):
        w = app.world
        specs = [(w.solver if m == SAME_MODE else m, w.integrator, {}) for m in self.chosen]
        try:
            app.compare.start(specs)
            self.error = ""
            app.panels.stats.show_compare = True
            app.notices.notify("comparing " + ", ".join([w.solver] + [ln.label for ln in app.compare.lanes]))
        except ValueError as exc:
            self.error = f"refused: {exc}"

    def running(self, app, cmp):
        for k, view in enumerate(cmp.VIEWS):
            if k:
                imgui.same_line()
            if imgui.radio_button(f"{view} view", cmp.view == view):
                app.compare_view.set_view(view)
            record(app, f"compare:view:{view}")
        if imgui.button("Restart from now"):
            cmp.restart()
        imgui.same_line()
        if imgui.button("Stop comparing"):
            cmp.stop()
            app.panels.stats.show_compare = False
            return
        record(app, "compare:stop")
        self.lane_line(LANE_COLORS[0], f"main: {app.world.solver}", "")
        for lane in cmp.lanes:
            self.lane_line(lane.color, lane.label, lane.waiting or
                           (f"{lane.behind} steps behind" if lane.behind else ""))
            if imgui.tree_node(f"settings##{id(lane)}"):
                self.lane_settings(cmp, lane)
                imgui.tree_pop()
        wrapped(DIM, "Any edit restarts the rivals from the scene as it is then.")
        record(app, "compare:help")

    @staticmethod
    def lane_line(color, label, note):
        imgui.color_button(f"##{label}", imgui.ImVec4(*color), 0, imgui.ImVec2(12, 12))
        imgui.same_line()
        imgui.text(label)
        if note:
            imgui.same_line()
            wrapped(AMBER, note)

    def lane_settings(self, cmp, lane):
        settings = lane.world.settings_for(lane.solver)
        for name, decl in settings.declared().items():
            ch, v = setting_widget(f"{name}##{id(lane)}", decl, settings[name])
            ch = typed(self.app, name, ch, integer=isinstance(decl.default, int))
            if ch:
                try:
                    cmp.set_setting(lane, name, v)
                    self.error = ""
                except (ValueError, KeyError) as exc:
                    self.error = f"refused: {exc}"
