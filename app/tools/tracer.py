"""Tracer tool: click a body to leave a trail behind that point of it (shift-click: remove the
body's tracers)."""
from __future__ import annotations

from ..picking import body_at
from .base import Tool


class TracerTool(Tool):
    name = "tracer"
    snaps = False
    help = "click a body: a trail behind that point (kept for the View section's trail seconds); " \
           "shift-click: remove its trails"

    def press(self, p, button, mods):
        from pyglet.window import key as K
        ed = self.editor
        b = body_at(ed.world, p)
        if b is None:
            ed.hint("no body here: click a body to trace a point of it", error=False)
            return
        if mods & K.MOD_SHIFT:
            n = ed.tracers.remove_body(b, ed.refs)
            ed.notify(f"removed {n} tracer{'s' if n != 1 else ''} of {b.name or b.id}")
            return
        ed.tracers.add(b, p, ed.refs, ed.world)
        ed.notify(f"tracing a point of {b.name or b.id}")

    def decorate(self, decor, cursor):
        for tr in self.editor.tracers.items:
            b = tr.ref.obj
            if b is not None and b.alive:
                decor.points.append((b.local_to_world(tr.local), 3.5, (*tr.color, 1.0)))
