"""Pointer and keyboard events for the scene, pushed onto the window's handler stack below imgui's
(so imgui sees every event first).  An event reaches the scene only when no panel takes it."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pyglet
from imgui_bundle import imgui
from pyglet.window import mouse

from .shortcuts import handle_key


class SceneInput:
    """Routes pyglet events of ``app`` (the Sandbox) to the camera, the active tool and the shortcuts."""

    def __init__(self, app):
        self.app = app
        self.cursor_px = np.array([app.width * 0.6, app.height * 0.5])
        self.panning = None
        self.tool_active = False

    @property
    def editor(self):
        return self.app.editor

    def _call_tool(self, fn, *args):
        try:
            fn(*args)
        except ValueError as exc:
            self.editor.notify(f"refused: {exc}", error=True)

    def on_panel(self, x, y) -> bool:
        """Does a pointer event at window pixel (x, y) (pyglet's, y up) land on a panel?  Judged
        by where the panels are drawn, not by where imgui saw the pointer in the last frame, so
        an event in the frame the pointer reaches (or leaves) a panel goes where it lands."""
        return self.app.panels.hits.covers(x, self.app.height - y)

    def scene_mouse(self, x, y) -> bool:
        """May a pointer event at (x, y) go to the scene (no panel there, kernels ready)?"""
        return self.app.warmup.ready and not self.on_panel(x, y)

    def update_hover(self):
        """The body under the pointer (drawn highlighted), none over a panel or while panning."""
        ed = self.editor
        if self.on_panel(*self.cursor_px) or self.panning:
            ed.hovered = None
            return
        try:
            ed.hovered = ed.world.query_point(tuple(ed.cursor))
        except ValueError:
            ed.hovered = None

    # -- pyglet events ---------------------------------------------------------------
    def on_mouse_motion(self, x, y, dx, dy):
        self.cursor_px = np.array([x, y], dtype=float)
        self.editor.cursor = self.app.camera.to_world(x, y)

    def on_mouse_press(self, x, y, button, modifiers):
        self.on_mouse_motion(x, y, 0, 0)
        if not self.scene_mouse(x, y):
            return
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
            self.panning = None
            return
        if button == mouse.LEFT and self.tool_active:
            self.tool_active = False
            self._call_tool(self.editor.tool.release, tuple(self.editor.cursor))

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

    def on_key_press(self, symbol, modifiers):
        io = imgui.get_io()
        if not (io.want_capture_keyboard or not self.app.warmup.ready):
            handle_key(self.app, symbol, modifiers)
        return pyglet.event.EVENT_HANDLED     # never the window's default (Esc would close it)
