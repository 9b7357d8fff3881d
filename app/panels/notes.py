"""Floating text: the message strip at the bottom of the scene, the compile note at its top, and
the compile progress shown there until the open scene's kernels are ready."""
from __future__ import annotations

from imgui_bundle import imgui

from .style import AMBER, DIM, GREEN, RED

# a note never takes focus as it appears: that took the keyboard from the field being typed in
NOTE_FLAGS = (imgui.WindowFlags_.no_decoration | imgui.WindowFlags_.always_auto_resize |
              imgui.WindowFlags_.no_inputs | imgui.WindowFlags_.no_saved_settings |
              imgui.WindowFlags_.no_focus_on_appearing | imgui.WindowFlags_.no_nav).value


def messages(app):
    """The last five messages younger than six seconds (errors red); clicks pass through."""
    msgs = app.notices.recent(6.0)
    if not msgs:
        return
    x0, _, x1, y1 = app.free_rect()
    imgui.set_next_window_pos(imgui.ImVec2(0.5 * (x0 + x1), y1 - 4), imgui.Cond_.always.value, imgui.ImVec2(0.5, 1.0))
    imgui.set_next_window_bg_alpha(0.85)
    flags = (imgui.WindowFlags_.no_decoration | imgui.WindowFlags_.always_auto_resize |
             imgui.WindowFlags_.no_saved_settings | imgui.WindowFlags_.no_focus_on_appearing |
             imgui.WindowFlags_.no_nav | imgui.WindowFlags_.no_inputs).value
    imgui.begin("##messages", None, flags)
    for text, error, _ in msgs[-5:]:
        imgui.text_colored(RED if error else GREEN, text)
    imgui.end()


def overlay_note(app, text):
    """One amber line at the top of the scene (e.g. a mode still compiling)."""
    x0, y0, x1, _ = app.free_rect()
    cap = app.ui_rects.get("caption")
    y = cap[3] + 4 if cap is not None else y0 + 14       # below the scene's caption, not over it
    imgui.set_next_window_pos(imgui.ImVec2(0.5 * (x0 + x1), y), imgui.Cond_.always.value, imgui.ImVec2(0.5, 0.0))
    imgui.begin("##note", None, NOTE_FLAGS)
    imgui.text_colored(AMBER, text)
    imgui.end()


def progress_window(app):
    """While the open scene's kernels compile (the launch's, then a scene's own mode): what
    stepping waits for and how much is left, at the top of the free area (the panels beside it
    already work).  Clicks pass through it."""
    x0, y0, x1, _ = app.free_rect()
    cap = app.ui_rects.get("caption")
    y = cap[3] + 4 if cap is not None else y0 + 14       # below the scene's caption, not over it
    imgui.set_next_window_pos(imgui.ImVec2(0.5 * (x0 + x1), y), imgui.Cond_.always.value, imgui.ImVec2(0.5, 0.0))
    imgui.set_next_window_size(imgui.ImVec2(min(560.0, max(x1 - x0 - 16, 200.0)), 0), imgui.Cond_.always.value)
    imgui.set_next_window_bg_alpha(0.85)
    imgui.begin("##progress", None, NOTE_FLAGS & ~imgui.WindowFlags_.always_auto_resize.value)
    frac, label = app.scene_wait.progress(app.world)
    # a later launch compiles only what a scene needs beyond the cache: not a "first launch"
    head = ("Compiling the physics kernels (first launch only)" if app.warmup.first_launch
            else "Compiling the kernels this scene needs (kept in the cache after)")
    imgui.push_text_wrap_pos(0)
    imgui.text_colored(AMBER, f"{head}: stepping starts when done")
    imgui.text_colored(DIM, "Meanwhile select, inspect, edit, pan, zoom and open scenes.")
    imgui.progress_bar(frac, imgui.ImVec2(-1, 0), f"{100 * frac:.0f}%")
    imgui.text_colored(DIM, f"{app.warmup.elapsed():.0f} s: {label}")
    imgui.pop_text_wrap_pos()
    a, b = imgui.get_window_pos(), imgui.get_window_size()
    app.ui_rects["progress"] = (a.x, a.y, a.x + b.x, a.y + b.y)
    app.ui_values["progress"] = label
    app.ui_values["progress_head"] = head
    imgui.end()


HINT_WRAP_PX = 340.0


def cursor_hint(app):
    """The editor's hint (why an input was refused) beside the point it is about: right of and
    above it, or left of / below it where it would run off the window ("no body her" at the right
    edge)."""
    h = app.editor.current_hint()
    if h is None:
        app.ui_rects.pop("hint", None)
        return
    text, p, error = h
    sx, sy = app.camera.to_screen(p)
    x, y = float(sx), app.height - float(sy)
    pad = imgui.get_style().window_padding
    size = imgui.calc_text_size(text, False, HINT_WRAP_PX)
    left = x + 16 + size.x + 2 * pad.x > app.width - 4
    below = y - 10 - size.y - 2 * pad.y < 4
    pos = imgui.ImVec2(x - 16 if left else x + 16, y + 10 if below else y - 10)
    imgui.set_next_window_pos(pos, imgui.Cond_.always.value, imgui.ImVec2(1.0 if left else 0.0, 0.0 if below else 1.0))
    imgui.set_next_window_bg_alpha(0.9)
    imgui.set_next_window_size_constraints(imgui.ImVec2(0, 0), imgui.ImVec2(HINT_WRAP_PX + 20, 400))
    imgui.begin("##hint", None, NOTE_FLAGS)
    imgui.push_text_wrap_pos(HINT_WRAP_PX)
    imgui.text_colored(RED if error else AMBER, text)
    imgui.pop_text_wrap_pos()
    a, b = imgui.get_window_pos(), imgui.get_window_size()
    app.ui_rects["hint"] = (a.x, a.y, a.x + b.x, a.y + b.y)
    imgui.end()


def scene_caption(app, text):
    """The scene's suggestion, dim, wrapped to the free area's width at its top left."""
    x0, y0, x1, _ = app.free_rect()
    imgui.set_next_window_pos(imgui.ImVec2(x0 + 8, y0 + 8), imgui.Cond_.always.value)
    imgui.set_next_window_bg_alpha(0.6)
    imgui.set_next_window_size_constraints(imgui.ImVec2(0, 0), imgui.ImVec2(max(x1 - x0 - 16, 100), 200))
    imgui.begin("##caption", None, NOTE_FLAGS)
    imgui.push_text_wrap_pos(max(x1 - x0 - 32, 80))
    imgui.text_colored(DIM, text)
    imgui.pop_text_wrap_pos()
    a, b = imgui.get_window_pos(), imgui.get_window_size()
    app.ui_rects["caption"] = (a.x, a.y, a.x + b.x, a.y + b.y)
    app.ui_values["caption"] = text
    imgui.end()
