"""Pointer and keyboard events for the scene, pushed onto the window's handler stack below imgui's
(so imgui sees every event first).  An event reaches the scene only when no panel takes it."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pyglet
from imgui_bundle import imgui
from pyglet.window import key, mouse

from .picking import body_at
from .shortcuts import handle_key

MODIFIER_KEYS = {key.LSHIFT, key.RSHIFT, key.LCTRL, key.RCTRL, key.LALT, key.RALT, key.LMETA, key.RMETA,
                 key.LWINDOWS, key.RWINDOWS, key.CAPSLOCK, key.NUMLOCK}


class SceneInput:
    """Routes pyglet events of ``app`` (the Sandbox) to the camera, the active tool and the shortcuts."""

    def __init__(self, app):
        self.app = app
        self.cursor_px = np.array([app.width * 0.6, app.height * 0.5])
        self.panning = None
        self.tool_active = False
        # keyboard focus: shortcuts fire only while the scene has it.  A press on a panel takes it
        # (keys typed into a field that has not or no longer has the keyboard must not act on the
        # scene); a press in the scene, Esc, moving the pointer into the scene once no text field
        # is active, or a field let go from the keyboard (Enter) with its value taken gives it
        # back; a press on a panel that activated no text field too.
        self.scene_keys = True
        self._panel_press_frame = None
        self._text_used = False
        self._typing = False       # a text field had the keyboard in the last frame

    @property
    def editor(self):
        return self.app.editor

    def _call_tool(self, fn, p, *args):
        """``fn(p, *args)``; a creation tool gets the point snapped to the grid while snapping."""
        if self.editor.tool.snaps:
            p = tuple(self.editor.snap.point(p))
        try:
            fn(p, *args)
        except ValueError as exc:
            self.editor.hint(f"refused: {exc}")

    def on_panel(self, x, y) -> bool:
        """Does a pointer event at window pixel (x, y) (pyglet's, y up) land on a panel?  Judged
        by where the panels are drawn, not by where imgui saw the pointer in the last frame, so
        an event in the frame the pointer reaches (or leaves) a panel goes where it lands."""
        return self.app.panels.hits.covers(x, self.app.height - y)

    def scene_mouse(self, x, y) -> bool:
        """May a pointer event at (x, y) go to the scene (no panel there)?  Also while the
        kernels compile: picks and frames read the preview's render data (``app.preview.hold``)."""
        return not self.on_panel(x, y)

    def update_hover(self):
        """The body under the pointer (drawn highlighted), none over a panel or while panning."""
        ed = self.editor
        if self.on_panel(*self.cursor_px) or self.panning:
            ed.hovered = None
            return
        try:
            ed.hovered = body_at(ed.world, tuple(ed.cursor))
        except ValueError:
            ed.hovered = None

    # -- pyglet events ---------------------------------------------------------------
    def after_frame(self):
        """Follow the panels' keyboard use (called once per frame after the UI is drawn)."""
        io = imgui.get_io()
        typing, self._typing = self._typing, io.want_text_input
        if io.want_text_input:
            self.scene_keys = False
            self._text_used = True
        elif typing and not imgui.is_any_mouse_down() and not self.editor.edit_error:
            # the field let go from the keyboard (Enter, Tab, Esc) with its value taken: Space
            # pauses again; after a refusal the keys stay away from the scene (typing on to
            # correct the value must not fire shortcuts)
            self._take_keys()
        elif (not self.scene_keys and not self._text_used and self._panel_press_frame is not None
              and self.app.frame_no > self._panel_press_frame + 1):
            self.scene_keys = True          # the press on the panel was a button, not a text field

    def _take_keys(self):
        self.scene_keys = True
        self._text_used = False
        self._panel_press_frame = None

    def on_mouse_motion(self, x, y, dx, dy):
        self.cursor_px = np.array([x, y], dtype=float)
        self.editor.cursor = self.app.camera.to_world(x, y)
        if not self.scene_keys and (dx or dy) and not imgui.get_io().want_text_input \
                and not self.on_panel(x, y):
            self._take_keys()

    def on_mouse_press(self, x, y, button, modifiers):
        self.on_mouse_motion(x, y, 0, 0)
        if self.on_panel(x, y):
            self.scene_keys = False
            self._text_used = False
            self._panel_press_frame = self.app.frame_no
        if not self.scene_mouse(x, y):
            return
        self._take_keys()
        if button in (mouse.RIGHT, mouse.MIDDLE):
            self.panning = (x, y)
            return
        if button == mouse.LEFT:
            self.tool_active = True
            self._call_tool(self.editor.tool.press, tuple(self.editor.cursor), button, modifiers)

    def on_mouse_drag(self, x, y, dx, dy, buttons, modifiers):
        self.on_mouse_motion(x, y, dx, dy)
        if self.panning is not None and buttons & (mouse.RIGHT | mouse.MIDDLE):
            self.app.camera.pan_pixels(dx, dy)
            self.editor.cursor = self.app.camera.to_world(x, y)
            return
        if self.tool_active and buttons & mouse.LEFT:
            self._call_tool(self.editor.tool.drag, tuple(self.editor.cursor))

    def on_mouse_release(self, x, y, button, modifiers):
        self.on_mouse_motion(x, y, 0, 0)
        if button in (mouse.RIGHT, mouse.MIDDLE):
            start, self.panning = self.panning, None
            if button == mouse.RIGHT and start is not None and abs(x - start[0]) + abs(y - start[1]) <= 3:
                if not self.editor.tool.right_click(tuple(self.editor.cursor)):   # a tool's own use first
                    self.context_menu()
            return
        if button == mouse.LEFT and self.tool_active:
            self.tool_active = False
            self._call_tool(self.editor.tool.release, tuple(self.editor.cursor))

    def context_menu(self):
        """A right click without a drag on a body: its context menu (nothing on empty space)."""
        try:
            b = body_at(self.editor.world, tuple(self.editor.cursor))
        except ValueError:
            return
        if b is not None:
            self.app.panels.context.open_at(b, self.editor.cursor)

    def on_mouse_scroll(self, x, y, scroll_x, scroll_y):
        if not self.scene_mouse(x, y):
            return
        self.app.camera.zoom_at(x, y, 1.15 ** scroll_y)
        self.editor.cursor = self.app.camera.to_world(x, y)

    def on_file_drop(self, x, y, paths):
        for p in paths:
            if str(p).lower().endswith(".json"):
                self.app.files.request_open(Path(p))
                return
        self.editor.notify("drop a .json scene file", error=True)

    def on_text(self, text):
        # imgui has taken the text already (its handler is above this one); a number field's
        # dropped letters are said, not lost
        self.app.panels.numbers.on_text(text)

    def on_key_press(self, symbol, modifiers):
        io = imgui.get_io()
        if io.want_capture_keyboard:     # (shortcuts work while compiling: a step waits, app.simulation)
            return pyglet.event.EVENT_HANDLED
        ctrl = modifiers & (key.MOD_CTRL | key.MOD_COMMAND)
        if symbol == key.ESCAPE:
            self._take_keys()
        if self.scene_keys or ctrl:
            handle_key(self.app, symbol, modifiers)
        elif symbol not in MODIFIER_KEYS:
            self.editor.hint("keys go to the panels now: click the scene (or move the pointer into it) "
                             "for shortcuts", error=False)
        return pyglet.event.EVENT_HANDLED     # never the window's default (Esc would close it)
