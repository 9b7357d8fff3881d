"""The panels as one UI: the side panel (its sections, top to bottom), the stats window, the
messages and dialogs, in the order imgui draws them each frame."""
from __future__ import annotations

from imgui_bundle import imgui

from .base import record_window
from .dialogs import Dialogs
from .inspector import InspectorSection
from .notes import messages, progress_window
from .scene import SceneSection
from .simulation import SimulationSection
from .solver import SolverSection
from .stats import StatsWindow
from .style import PANEL_W
from .tools import ToolsSection
from .view import ViewSection

#: the side panel's sections, top to bottom (add a new section here)
SECTIONS = (SimulationSection, ToolsSection, InspectorSection, SolverSection, SceneSection, ViewSection)


class Panels:
    """``over_ui``: the pointer was over a panel in the last frame; ``show_stats``: the stats
    window is open."""

    def __init__(self, app):
        self.app = app
        self.sections = [cls(app) for cls in SECTIONS]
        self.tools = next(s for s in self.sections if isinstance(s, ToolsSection))
        self.stats = StatsWindow(app)
        self.dialogs = Dialogs(app)
        self.over_ui = False
        self.show_stats = True

    def confirm(self, message, on_discard, on_save=None):
        self.dialogs.confirm(message, on_discard, on_save)

    def draw(self):
        app = self.app
        io = imgui.get_io()
        app.ui_rects.pop("main_window", None)
        app.ui_rects.pop("stats_window", None)
        if not app.warmup.ready:
            progress_window(app)
            return
        self.main_window()
        if self.show_stats:
            self.stats.draw()
        messages(app)
        self.dialogs.draw()
        self.tools.drop()
        self.over_ui = imgui.is_window_hovered(imgui.HoveredFlags_.any_window.value) or io.want_capture_mouse

    def main_window(self):
        app = self.app
        io = imgui.get_io()
        imgui.set_next_window_pos(imgui.ImVec2(8, 8), imgui.Cond_.first_use_ever.value)
        imgui.set_next_window_size(imgui.ImVec2(PANEL_W, io.display_size.y - 16), imgui.Cond_.first_use_ever.value)
        imgui.begin(f"Stelkropp - {app.editor.doc.title}###main", None, imgui.WindowFlags_.no_collapse.value)
        for section in self.sections:
            if section.header():
                section.draw()
        record_window(app, "main_window")
        imgui.end()
