"""A refused field edit is said beside the field: in a bubble right of the side panel, at the
height of the field that was refused (where the user is looking).  Inside the panel the message
pushed every field below it down by a line or two, so the next click landed on another field."""
from __future__ import annotations

from imgui_bundle import imgui

from .notes import NOTE_FLAGS
from .style import RED

WRAP_PX = 380.0


class RefusalBubble:
    """Remembers where the refused field is (the editor calls ``refused`` right after the field's
    widget, while imgui's last item is that field) and draws ``editor.edit_error`` beside it."""

    def __init__(self, app):
        self.app = app
        self.field = None            # (x0, y0, x1, y1) of the refused field (window pixels, y down)
        app.editor.on_refusal.append(self.refused)

    def refused(self, at=None):
        if at is not None:         # a refusal between frames (keys typed into a field) says where
            self.field = at
            return
        a, b = imgui.get_item_rect_min(), imgui.get_item_rect_max()
        self.field = (a.x, a.y, b.x, b.y)

    def draw(self):
        app = self.app
        text = app.editor.edit_error
        if not text or self.field is None:
            app.ui_rects.pop("refusal", None)
            return
        x0, y0, x1, _ = self.field
        panel = app.ui_rects.get("main_window")
        left = panel[2] + 6 if panel and panel[0] <= x0 <= panel[2] else x1 + 8
        # at the field's height, but inside the window (a field at the bottom of the panel had
        # its message cut off below)
        pad = imgui.get_style().window_padding
        tall = imgui.calc_text_size(text, False, WRAP_PX).y + 2 * pad.y
        top = max(0.0, min(y0 - 3, app.height - tall - 4))
        imgui.set_next_window_pos(imgui.ImVec2(left, top), imgui.Cond_.always.value)
        imgui.set_next_window_bg_alpha(0.92)
        imgui.begin("##refusal", None, NOTE_FLAGS)
        imgui.push_text_wrap_pos(WRAP_PX)
        imgui.text_colored(RED, text)
        imgui.pop_text_wrap_pos()
        a, b = imgui.get_window_pos(), imgui.get_window_size()
        app.ui_rects["refusal"] = (a.x, a.y, a.x + b.x, a.y + b.y)
        imgui.end()
