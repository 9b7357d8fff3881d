"""The panels as one UI: the side panel (its sections, top to bottom), the stats window, the
messages and dialogs, in the order imgui draws them each frame."""
from __future__ import annotations

from imgui_bundle import imgui

from .base import record_window
from .compare import CompareSection
from .context import ContextMenu
from .dialogs import Dialogs
from .hits import PanelHits
from .inspector import InspectorSection
from .plot_tab import PlotTab
from ..scene_caption import caption_of
from .notes import cursor_hint, messages, progress_window, scene_caption
from .number_typing import NumberTyping
from .refusal import RefusalBubble
from .scene import SceneSection
from .simulation import SimulationSection
from .solver import SolverSection
from .stats import StatsWindow, stats_default_rect
from .style import PANEL_W, label_room
from .tools import ToolsSection
from .view import ViewSection

#: the side panel's sections, top to bottom (add a new section here)
SECTIONS = (SimulationSection, CompareSection, ToolsSection, InspectorSection, SolverSection, SceneSection,
            ViewSection)


class Panels:
    """The imgui UI of ``app``; ``hits`` says where its windows are (event routing);
    ``show_stats``: the stats window is open."""

    def __init__(self, app, imgui_ctx):
        self.app = app
        self.hits = PanelHits(imgui_ctx)
        self.sections = [cls(app) for cls in SECTIONS]
        self.tools = next(s for s in self.sections if isinstance(s, ToolsSection))
        self.scene = next(s for s in self.sections if isinstance(s, SceneSection))
        self.solver = next(s for s in self.sections if isinstance(s, SolverSection))
        self.stats = StatsWindow(app)
        self.plot = PlotTab(app)
        self.context = ContextMenu(app)
        self.dialogs = Dialogs(app)
        self.refusal = RefusalBubble(app)      # a refused field's message, beside the field
        self.numbers = NumberTyping(app)       # letters typed into a number field: refused in words
        self.show_stats = True

    def ask(self, title, lines, buttons):
        self.dialogs.ask(title, lines, buttons)

    def default_rects(self, width, height):
        """Where the side panel and the stats window open (window pixels, y down)."""
        rects = [(8.0, 8.0, 8.0 + PANEL_W, height - 8.0)]
        if self.show_stats:
            rects.append(stats_default_rect(width, height))
        return rects

    def close(self):
        """Stop what the panels run in the background (the Find settings search)."""
        self.solver.find.finder.close()

    def focus_save_as(self):
        """Open the Scene section with the keyboard in its Save-as field (Ctrl+Shift+S)."""
        self.app.show_ui = True
        self.scene.focus_save_as = True

    def draw(self):
        app = self.app
        app.ui_rects.pop("main_window", None)
        app.ui_rects.pop("stats_window", None)
        self.main_window()          # from the first frame: only stepping waits for the kernels
        self.solver.find.tick()
        if self.show_stats:
            self.stats.draw()
        self.caption()
        messages(app)
        cursor_hint(app)
        self.refusal.draw()
        self.dialogs.draw()
        self.context.draw()
        self.tools.drop()
        if app.scene_wait.waiting(app.world):
            progress_window(app)

    def caption(self):
        app = self.app
        text = caption_of(app.world.metadata)
        if text is None:
            app.ui_rects.pop("caption", None)
            app.ui_values.pop("caption", None)
            return
        scene_caption(app, text)

    def main_window(self):
        app = self.app
        io = imgui.get_io()
        imgui.set_next_window_pos(imgui.ImVec2(8, 8), imgui.Cond_.first_use_ever.value)
        imgui.set_next_window_size(imgui.ImVec2(PANEL_W, io.display_size.y - 16), imgui.Cond_.first_use_ever.value)
        imgui.begin(f"Stelkropp - {app.editor.doc.title}###main", None, imgui.WindowFlags_.no_collapse.value)
        imgui.push_item_width(-label_room(app.world.settings.declared().keys()))
        # the right edge of the content (labels are clipped beyond it)
        app.ui_rects["main_content"] = (imgui.get_cursor_screen_pos().x, 0.0,
                                        imgui.get_cursor_screen_pos().x + imgui.get_content_region_avail().x, 0.0)
        for section in self.sections:
            if section.header():
                section.draw()
        imgui.pop_item_width()
        record_window(app, "main_window")
        imgui.end()
