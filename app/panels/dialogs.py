"""Dialogs: questions (unsaved edits, overwrite a file), the crash-recovery offer, and the window
listing a failed load's problems."""
from __future__ import annotations

import time

from imgui_bundle import imgui

from .base import record
from .style import AMBER, DIM, RED

WRAP_PX = 520.0       # dialog text wraps at this width (a failed load's lines name long paths)


class Dialogs:
    def __init__(self, app):
        self.app = app
        self.question = None          # (title, lines, [(button label, callback or None)])
        self.autosave_offer = None    # (path, mtime, origin)

    def ask(self, title, lines, buttons):
        """Put a question in a modal dialog: ``lines`` of text, one button per (label, callback);
        a callback of None (and Esc) only closes the dialog.  A callback may ask again."""
        self.question = (title, list(lines), list(buttons))

    @property
    def open_title(self):
        """The title of the question being asked, or None."""
        return self.question[0] if self.question else None

    def draw(self):
        self.scene_errors()
        self.ask_window()
        self.restore_offer()

    @staticmethod
    def _centre_next():
        io = imgui.get_io()
        imgui.set_next_window_pos(imgui.ImVec2(io.display_size.x * 0.5, io.display_size.y * 0.4),
                                  imgui.Cond_.appearing.value, imgui.ImVec2(0.5, 0.5))

    def ask_window(self):
        if self.question is None:
            return
        title = self.question[0]
        if not imgui.is_popup_open(title):
            imgui.open_popup(title)
        self._centre_next()
        opened, _ = imgui.begin_popup_modal(title, None, imgui.WindowFlags_.always_auto_resize.value)
        if not opened:
            return
        _, lines, buttons = self.question
        imgui.push_text_wrap_pos(imgui.get_cursor_pos_x() + WRAP_PX)
        for i, line in enumerate(lines):
            if i:
                imgui.text_colored(AMBER, line)
            else:
                imgui.text(line)
        imgui.pop_text_wrap_pos()
        chosen = None
        for i, (label, fn) in enumerate(buttons):
            if i:
                imgui.same_line()
            if imgui.button(label):
                chosen = (fn,)
            record(self.app, f"dialog:{label}")
        if chosen is None and imgui.is_key_pressed(imgui.Key.escape):
            chosen = (None,)
        if chosen is not None:
            self.question = None
            imgui.close_current_popup()
            if chosen[0] is not None:
                chosen[0]()
        imgui.end_popup()

    def restore_offer(self):
        if self.autosave_offer is not None and not imgui.is_popup_open("Restore autosave?"):
            imgui.open_popup("Restore autosave?")
        self._centre_next()
        opened, _ = imgui.begin_popup_modal("Restore autosave?", None, imgui.WindowFlags_.always_auto_resize.value)
        if not opened:
            return
        path, when, origin = self.autosave_offer or (None, 0, None)
        imgui.text("Stelkropp did not exit cleanly last time.")
        imgui.text(f"An autosave from {time.strftime('%Y-%m-%d %H:%M', time.localtime(when))} exists"
                   + (f" (of {origin})." if origin else "."))
        if imgui.button("Restore it"):
            self.autosave_offer = None
            imgui.close_current_popup()
            self.app.files.restore_autosave(path, origin)
        imgui.same_line()
        if imgui.button("Discard it"):
            self.autosave_offer = None
            imgui.close_current_popup()
            self.app.autosaver.discard(path)
        imgui.end_popup()

    def scene_errors(self):
        """A load that failed: its problems, until dismissed (the current scene stays)."""
        app = self.app
        errors = app.files.errors
        if not errors:
            return
        x0, _, x1, y1 = app.free_rect()
        imgui.set_next_window_pos(imgui.ImVec2(0.5 * (x0 + x1), y1 - 40),
                                  imgui.Cond_.appearing.value, imgui.ImVec2(0.5, 1.0))
        imgui.set_next_window_size_constraints(imgui.ImVec2(300, 0), imgui.ImVec2(560, 400))
        flags = (imgui.WindowFlags_.always_auto_resize | imgui.WindowFlags_.no_saved_settings |
                 imgui.WindowFlags_.no_collapse).value
        imgui.begin("Scene not loaded###sceneerr", None, flags)
        imgui.push_text_wrap_pos(imgui.get_cursor_pos_x() + WRAP_PX)
        imgui.text_colored(RED, "Could not load the scene; the current one stays.")
        imgui.begin_group()
        for line in errors[:20]:
            imgui.bullet()                 # bullet_text does not wrap: a long path ran off the dialog
            imgui.text_wrapped(line)
        imgui.end_group()
        record(app, "scene_errors:lines")
        if len(errors) > 20:
            imgui.text_colored(DIM, f"... and {len(errors) - 20} more")
        imgui.pop_text_wrap_pos()
        if imgui.button("Dismiss"):
            app.files.errors = []
        a, b = imgui.get_window_pos(), imgui.get_window_size()
        app.ui_rects["scene_errors"] = (a.x, a.y, a.x + b.x, a.y + b.y)
        imgui.end()
