"""Keyboard shortcuts of the scene (not of a focused text field): one table, read top to bottom.

To add one: a row ``(key, needs_ctrl, action)``; ``action(app, shift)`` gets the window and
whether Shift was held.  Tool keys 1..9 follow ``app.tools.TOOLS``.
"""
from __future__ import annotations

from pyglet.window import key as K

from .gluing import glue_selection, unglue_selection


def _overlay(name):
    def toggle(app, shift):
        setattr(app.overlays, name, not getattr(app.overlays, name))
    return toggle


def _cancel(app, shift):
    app.editor.tool.cancel()
    app.editor.select(None)


def _toggle_snap(app, shift):
    snap = app.editor.snap
    snap.on = not snap.on
    app.notices.notify(f"snapping {'on' if snap.on else 'off'} (grid {snap.grid:g} m, {snap.angle:g} deg)")


def _toggle_ui(app, shift):
    app.show_ui = not app.show_ui


def _quit(app, shift):
    app.on_close()           # as the window's close button: unsaved edits are asked about first


SHORTCUTS = (
    (K.Q, True, _quit),
    (K.Z, True, lambda app, shift: app.editor.redo() if shift else app.editor.undo()),
    (K.Y, True, lambda app, shift: app.editor.redo()),
    (K.S, True, lambda app, shift: app.panels.focus_save_as() if shift else app.files.save()),
    (K.D, True, lambda app, shift: app.editor.duplicate_selection()),
    (K.C, True, lambda app, shift: app.editor.copy_selection()),
    (K.V, True, lambda app, shift: app.editor.paste()),
    (K.G, True, lambda app, shift: unglue_selection(app.editor) if shift else glue_selection(app.editor)),
    (K.SPACE, False, lambda app, shift: app.sim.toggle_run()),
    (K.S, False, lambda app, shift: app.sim.step_once()),
    (K.R, False, lambda app, shift: app.files.request_reset()),
    (K.F, False, lambda app, shift: app.fit()),
    (K.H, False, _toggle_ui),
    (K.L, False, lambda app, shift: app.editor.toggle_follow()),
    (K.G, False, _toggle_snap),
    (K.DELETE, False, lambda app, shift: app.editor.delete_selection()),
    (K.BACKSPACE, False, lambda app, shift: app.editor.delete_selection()),
    (K.T, False, lambda app, shift: app.editor.toggle_static()),
    (K.C, False, _overlay("contacts")),
    (K.B, False, _overlay("aabbs")),
    (K.Q, False, _overlay("quadtree")),
    (K.V, False, _overlay("velocities")),
    (K.M, False, _overlay("com")),
    (K.ESCAPE, False, _cancel),
)


def handle_key(app, symbol, modifiers) -> bool:
    """Run the shortcut for ``symbol``; True if one matched.  The active tool sees the key first."""
    ctrl = bool(modifiers & (K.MOD_CTRL | K.MOD_COMMAND))
    shift = bool(modifiers & K.MOD_SHIFT)
    ed = app.editor
    if ed.tool.key(symbol):
        return True
    for sym, needs_ctrl, action in SHORTCUTS:       # the first row that matches wins
        if sym == symbol and (ctrl or not needs_ctrl):
            action(app, shift)
            return True
    n_tools = min(9, len(ed.tool_names))
    if K._1 <= symbol < K._1 + n_tools:
        ed.set_tool(ed.tool_names[symbol - K._1])
        return True
    return False

