"""Spring tool: drag from a body to another body, or to empty space for a world anchor."""
from __future__ import annotations

import numpy as np

from ..commands import AddSpring
from ..picking import body_at
from .base import PREVIEW, Tool


class SpringTool(Tool):
    name = "spring"
    snaps = False
    help = "drag from a body to another body (or to empty space: a world anchor)"

    def __init__(self, editor):
        super().__init__(editor)
        self.a = None
        self.pa = None
        self.local_a = None

    def press(self, p, button, mods):
        b = body_at(self.editor.world, p)
        if b is None:
            self.editor.notify("start a spring on a body")
            return
        self.a, self.pa, self.local_a = b, np.array(p, dtype=float), b.world_to_local(p)

    def release(self, p):
        if self.a is None:
            return
        ed = self.editor
        a, local_a = self.a, self.local_a
        self.a = None
        if not a.alive:
            return
        b = body_at(ed.world, p)
        if b is a:
            b = None if np.hypot(*(np.array(p) - self.pa)) * ed.camera.scale > 10 else a
            if b is a:
                return  # a click on one body: nothing
        opts = ed.tool_options
        spec = {"a": ed.refs.of(a), "b": None if b is None else ed.refs.of(b),
                "anchor_a": local_a, "anchor_b": tuple(map(float, p)) if b is None else b.world_to_local(p),
                "stiffness": opts.spring_stiffness, "damping": opts.spring_damping, "rest_length": None,
                "name": None}
        ed.create(AddSpring(spec))

    def cancel(self):
        self.a = None

    def decorate(self, decor, cursor):
        if self.a is not None and self.a.alive:
            pa = self.a.local_to_world(self.local_a)
            decor.segments.append((pa, cursor, 2.0, PREVIEW))
            decor.points.append((pa, 4.0, PREVIEW))
