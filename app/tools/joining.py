"""What the joint tools share: picking the bodies to join under the pointer and making the joint
through an undoable command (``AddJoint``), selected once made."""
from __future__ import annotations

import numpy as np

from ..commands import AddJoint
from ..picking import bodies_at
from .base import Tool


def pair_at(world, p):
    """(a, b) for a joint at world point ``p``: the two topmost bodies there (b None: only one, so
    a joins the background), or None if no body is there.  A static body goes second, so the
    joint's angles, speeds and motor are the moving body's relative to it."""
    under = bodies_at(world, p)
    if not under:
        return None
    a = under[0]
    b = under[1] if len(under) > 1 else None
    if b is not None and a.kind == "static" and b.kind != "static":
        a, b = b, a
    return a, b


def pick_pair(editor, p, what):
    """``pair_at`` with the refusals said at the pointer (nothing there; a static body alone)."""
    pair = pair_at(editor.world, p)
    if pair is None:
        editor.hint(f"click a body to {what}")
        return None
    a, b = pair
    if a.kind == "static" and (b is None or b.kind == "static"):
        editor.hint(f"nothing to {what}: the bodies here are static (they do not move)")
        return None
    return pair


def add_joint(editor, kind, a, b, **fields):
    """Create the joint (one undoable command) and select it; a refusal is hinted at the pointer."""
    spec = {"kind": kind, "a": editor.refs.of(a), "b": None if b is None else editor.refs.of(b),
            "fields": fields}
    editor.create(AddJoint(spec))


class ClickJointTool(Tool):
    """A joint made by one click over the bodies it joins (hinge, motor, fixate): subclasses give
    ``kind``, ``verb`` (for the hints) and :meth:`fields`."""

    snaps = False
    kind = ""
    verb = "join"

    def fields(self, a, b, p) -> dict:
        raise NotImplementedError

    def press(self, p, button, mods):
        pair = pick_pair(self.editor, p, self.verb)
        if pair is not None:
            a, b = pair
            add_joint(self.editor, self.kind, a, b, **self.fields(a, b, tuple(map(float, p))))


class DragJointTool(Tool):
    """A joint dragged out from a body (slider, rope): the press picks the bodies, the release
    point finishes the joint in :meth:`finish`; a drag shorter than MIN_PX pixels does nothing."""

    snaps = False
    MIN_PX = 8.0
    verb = "join"

    def __init__(self, editor):
        super().__init__(editor)
        self.start = None       # (a, b, press point)

    def pick(self, p):
        return pick_pair(self.editor, p, self.verb)

    def press(self, p, button, mods):
        pair = self.pick(p)
        self.start = None if pair is None else (*pair, np.array(p, dtype=float))

    def release(self, p):
        if self.start is None:
            return
        a, b, p0 = self.start
        self.start = None
        if not a.alive or (b is not None and not b.alive):
            return
        p1 = np.array(p, dtype=float)
        if np.hypot(*(p1 - p0)) * self.editor.camera.scale < self.MIN_PX:
            self.clicked(a, b, p0)
            return
        self.finish(a, b, p0, p1)

    def clicked(self, a, b, p0):
        """A press and release in one place: by default a hint that the tool needs a drag."""
        self.editor.hint(f"drag to {self.verb} (a click alone makes nothing)", error=False)

    def finish(self, a, b, p0, p1):
        raise NotImplementedError

    def cancel(self):
        self.start = None
