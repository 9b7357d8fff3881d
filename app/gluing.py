"""Glue (Ctrl+G) and unglue (Ctrl+Shift+G): the selected bodies become one compound body, or a
compound body falls apart into one body per fixture (issue 13).  Both are undoable commands
(app.commands.Glue, Unglue); a refusal from the core becomes a notice."""
from __future__ import annotations

import physics

from .commands import Glue, Unglue


def glue_selection(editor) -> None:
    bodies = [s for s in editor.selection if isinstance(s, physics.Body) and s.alive]
    if len(bodies) < 2:
        editor.notify("glue: select two or more bodies (Shift+click or a box), then Ctrl+G", error=True)
        return
    try:
        cmd = Glue(editor, bodies)
        editor.tool.cancel()
        editor.execute(cmd)
    except ValueError as exc:
        editor.notify(f"glue refused: {exc}", error=True)
        return
    editor.select(cmd.add.ref.obj)
    n = len(cmd.add.ref.obj.fixtures)
    editor.notify(f"glued {len(bodies)} bodies into one of {n} fixtures (Ctrl+Z undoes)")


def unglue_selection(editor) -> None:
    bodies = [s for s in editor.selection if isinstance(s, physics.Body) and s.alive]
    if len(bodies) != 1 or len(bodies[0].fixtures) < 2:
        editor.notify("unglue: select one body made of several fixtures, then Ctrl+Shift+G", error=True)
        return
    try:
        cmd = Unglue(editor, bodies[0])
        editor.tool.cancel()
        editor.execute(cmd)
    except ValueError as exc:
        editor.notify(f"unglue refused: {exc}", error=True)
        return
    editor.selection = list(cmd.bodies)
    editor.notify(f"unglued into {len(cmd.bodies)} bodies (Ctrl+Z undoes)")
