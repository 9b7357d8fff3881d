"""Dialogs: "unsaved edits" before they would be lost, the crash-recovery offer, and the window
listing a failed load's problems."""
from __future__ import annotations

import time

from imgui_bundle import imgui

from .style import AMBER, DIM, PANEL_W, RED, STATS_W


class Dialogs:
    def __init__(self, app):
        self.app = app
        self.pending_confirm = None   # (message, on_discard, on_save)
        self.autosave_offer = None    # (path, mtime, origin)

    def confirm(self, message, on_discard, on_save=None):
        """Ask before unsaved edits are lost: discard (``on_discard``), save first (``on_save``), cancel."""
        self.pending_confirm = (message, on_discard, on_save)

    def draw(self):
        self.scene_errors()
        self.unsaved()
        self.restore_offer()

    @staticmethod
    def _centre_next():
        io = imgui.get_io()
        imgui.set_next_window_pos(imgui.ImVec2(io.display_size.x * 0.5, io.display_size.y * 0.4),
                                  imgui.Cond_.appearing.value, imgui.ImVec2(0.5, 0.5))

    def unsaved(self):
        if self.pending_confirm is not None and not imgui.is_popup_open("Unsaved edits"):
            imgui.open_popup("Unsaved edits")
        self._centre_next()
        opened, _ = imgui.begin_popup_modal("Unsaved edits", None, imgui.WindowFlags_.always_auto_resize.value)
        if not opened:
            return
        msg, on_discard, on_save = self.pending_confirm or ("", None, None)
        imgui.text(msg)
        imgui.text_colored(AMBER, "The scene has unsaved edits.")
        if on_save is not None and imgui.button("Save, then continue"):
            self.pending_confirm = None
            imgui.close_current_popup()
            on_save()
            imgui.same_line()
        elif on_save is not None:
            imgui.same_line()
        if imgui.button("Discard edits"):
            self.pending_confirm = None
            imgui.close_current_popup()
            on_discard()
        imgui.same_line()
        if imgui.button("Cancel") or imgui.is_key_pressed(imgui.Key.escape):
            self.pending_confirm = None
            imgui.close_current_popup()
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
            self.app.autosaver.discard()
        imgui.end_popup()

    def scene_errors(self):
        """A load that failed: its problems, until dismissed (the current scene stays)."""
        app = self.app
        errors = app.files.errors
        if not errors:
            return
        io = imgui.get_io()
        imgui.set_next_window_pos(imgui.ImVec2(io.display_size.x * 0.5 + 0.5 * (PANEL_W - STATS_W),
                                               io.display_size.y - 48),
                                  imgui.Cond_.appearing.value, imgui.ImVec2(0.5, 1.0))
        imgui.set_next_window_size_constraints(imgui.ImVec2(300, 0), imgui.ImVec2(560, 400))
        flags = (imgui.WindowFlags_.always_auto_resize | imgui.WindowFlags_.no_saved_settings |
                 imgui.WindowFlags_.no_collapse).value
        imgui.begin("Scene not loaded###sceneerr", None, flags)
        imgui.push_text_wrap_pos(imgui.get_cursor_pos_x() + 520)
        imgui.text_colored(RED, "Could not load the scene; the current one stays.")
        for line in errors[:20]:
            imgui.bullet_text(line)
        if len(errors) > 20:
            imgui.text_colored(DIM, f"... and {len(errors) - 20} more")
        imgui.pop_text_wrap_pos()
        if imgui.button("Dismiss"):
            app.files.errors = []
        a, b = imgui.get_window_pos(), imgui.get_window_size()
        app.ui_rects["scene_errors"] = (a.x, a.y, a.x + b.x, a.y + b.y)
        imgui.end()
