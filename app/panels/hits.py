"""Where the panels are, for routing pointer events: the rectangles of the imgui windows drawn in
the last frame that take mouse input, and whether a popup or an active widget holds the mouse."""
from __future__ import annotations

from imgui_bundle import imgui

PAD = 4.0   # imgui's resize borders reach a few pixels beyond a window's rectangle
_PASS = (imgui.WindowFlags_.no_mouse_inputs.value | imgui.WindowFlags_.tooltip.value)
_POPUP = imgui.WindowFlags_.popup.value | imgui.WindowFlags_.modal.value


class PanelHits:
    """Refreshed once per frame after ``imgui.render()`` (windows are placed by then)."""

    def __init__(self, ctx):
        self.ctx = ctx
        self.rects: list[tuple[float, float, float, float]] = []   # x0, y0, x1, y1 (y down)
        self.blocked = False      # a popup/modal is open or a widget is held: no pointer event is the scene's

    def refresh(self):
        rects, popup = [], False
        for w in self.ctx.windows:
            if not w.active or w.hidden or w.flags & _PASS:
                continue
            if w.flags & _POPUP:
                popup = True
            x, y, sx, sy = w.pos.x, w.pos.y, w.size.x, w.size.y
            rects.append((x - PAD, y - PAD, x + sx + PAD, y + sy + PAD))
        self.rects = rects
        self.blocked = popup or imgui.is_any_item_active()

    def covers(self, x, y_down) -> bool:
        """Is window pixel (x, y measured from the top) on a panel (or held by one)?"""
        if self.blocked:
            return True
        return any(x0 <= x <= x1 and y0 <= y_down <= y1 for x0, y0, x1, y1 in self.rects)

    def clear(self):
        """No panels drawn (hidden with H, or before the first frame)."""
        self.rects = []
        self.blocked = False
