"""Glue (Ctrl+G) and unglue (Ctrl+Shift+G): the selected bodies become one compound body, or a
compound body falls apart into one body per fixture (issue 13).  Both are undoable commands
(:class:`Glue`, :class:`Unglue`); a refusal from the core becomes a notice.

The springs and joints on the bodies stay: each end moves onto the body that replaces its own,
at the same world anchor (app.reattach).  One between two bodies glued together would hold the
compound to itself: it is dropped, and the notice and the undo text say so.  The tracers and
lasers on the bodies move the same way, keeping their world points.  Undo removes the new bodies
and brings back the old ones with their springs, joints, tracers and lasers exactly as they were.
"""
from __future__ import annotations

import numpy as np

import physics

from .commands import AddBody, Command, RemoveBodies, make_joint_from, make_spring
from .fixture_specs import glued_spec, unglued_specs
from .reattach import Place, moved_joint, moved_spring, nearest_part, part_place


def _plural(n, word):
    return f"{n} {word}" + ("" if n == 1 else "s")


class _Reattaching(Command):
    """What Glue and Unglue share: remove bodies (``self.remove``), add their replacements
    (``self.adds``), then remake the removed springs and joints on the replacements under their
    own Refs (later commands in the history still find them); ``place`` maps the ends."""

    def __init__(self, app, bodies, adds):
        self.remove = RemoveBodies(app, bodies)
        self.adds = adds
        self.kept = []                  # the Refs of the springs and joints remade
        self.marks = []                 # (tracer or laser, its ref, local point, angle, index) moved
        self.dropped = {"spring": 0, "joint": 0}

    def place(self, ref, p):
        raise NotImplementedError

    def do(self, app):
        self.remove.do(app)
        done = []
        try:
            for a in self.adds:
                a.do(app)
                done.append(a)
            self._remake(app)
            self._move_marks(app)
        except ValueError:
            self._unmake(app)
            for a in reversed(done):
                a.undo(app)
            self.remove.undo(app)
            raise

    def _remake(self, app):
        self.kept, self.dropped = [], {"spring": 0, "joint": 0}
        for what, items, moved, make in (("spring", self.remove.springs, moved_spring, make_spring),
                                         ("joint", self.remove.joints, moved_joint, make_joint_from)):
            for ref, spec in items:
                new = moved(spec, self.place)
                if new is None:
                    self.dropped[what] += 1
                    continue
                app.refs.rebind(ref, make(app.world, new))
                self.kept.append(ref)

    def _move_marks(self, app):
        """The tracers and lasers on a removed body go onto its replacement at the same world
        point (an emitter shining the same world direction), as the springs and joints do: left
        on the removed body, a trail would stop and a beam vanish.  ``undo`` puts them back."""
        removed = {id(r) for r in self.remove.refs}
        self.marks = []
        for item in [*app.tracers.items, *app.lasers.items]:
            pl = self.place(item.ref, item.local) if id(item.ref) in removed else None
            if pl is None:
                continue
            angle = getattr(item, "angle", None)
            self.marks.append((item, item.ref, item.local, angle, item.index))
            item.ref, item.local = pl.ref, tuple(map(float, pl.rot @ np.asarray(item.local) + pl.off))
            if angle is not None:
                item.angle = angle + pl.turn
            new_id = pl.ref.obj.id
            item.index = next((k for k, b in enumerate(app.world.bodies) if b.id == new_id), item.index)

    def _unmove_marks(self):
        for item, ref, local, angle, index in reversed(self.marks):
            item.ref, item.local, item.index = ref, local, index
            if angle is not None:
                item.angle = angle
        self.marks = []

    def _unmake(self, app):
        for ref in reversed(self.kept):
            if ref.obj.alive:
                app.deselect(ref.obj)
                app.world.remove(ref.obj)
        self.kept = []

    def undo(self, app):
        self._unmove_marks()
        self._unmake(app)
        for a in reversed(self.adds):
            a.undo(app)
        self.remove.undo(app)

    def kept_text(self) -> str:
        """'; kept 1 spring and 2 joints; dropped 1 joint between glued bodies' (empty if neither)."""
        kept = {"spring": 0, "joint": 0}
        for ref in self.kept:
            kept["spring" if isinstance(ref.obj, physics.Spring) else "joint"] += 1
        out = ""
        for verb, counts in (("kept", kept), ("dropped", self.dropped)):
            said = [_plural(n, what) for what, n in counts.items() if n]
            if said:
                out += f"; {verb} {' and '.join(said)}" + (" between glued bodies" if verb == "dropped" else "")
        return out


class Glue(_Reattaching):
    """Bodies -> one body holding all their fixtures where they are (app.fixture_specs.glued_spec),
    in the first body's frame; their springs and joints re-attached to it at the same world points."""

    def __init__(self, app, bodies):
        super().__init__(app, bodies, [AddBody(glued_spec(bodies), "glue")])
        self.n = len(bodies)
        # each body's place in the compound: fixed by the bodies' placement now (a redo reuses it)
        self.places = {app.refs.of(b): part_place(None, bodies[0], b) for b in bodies}

    @property
    def add(self):
        return self.adds[0]

    @property
    def label(self):
        return f"glue {self.n} bodies" + self.kept_text()

    def place(self, ref, p):
        pl = self.places.get(ref)
        return None if pl is None else pl._replace(ref=self.add.ref)


class Unglue(_Reattaching):
    """A body -> one body per fixture (a chain stays whole), each moving as its part did and in
    the body's own frame; each spring or joint end goes to the part its anchor lies in (else the
    nearest part)."""

    def __init__(self, app, body):
        specs = unglued_specs(body)
        super().__init__(app, [body], [AddBody(spec, "unglue") for spec in specs])
        self.ref = app.refs.of(body)
        self.shapes = [s["shape"] for s in specs]

    @property
    def label(self):
        return "unglue body" + self.kept_text()

    def place(self, ref, p):
        if ref is not self.ref:
            return None
        k = nearest_part(self.shapes, p)
        return Place(self.adds[k].ref, np.eye(2), np.zeros(2), 0.0)

    @property
    def bodies(self):
        return [a.ref.obj for a in self.adds]


def glue_selection(editor) -> None:
    """Ctrl+G: glue the selected bodies (two or more) and select the compound."""
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
    editor.notify(f"glued {len(bodies)} bodies into one of {n} fixtures{cmd.kept_text()} (Ctrl+Z undoes)")


def unglue_selection(editor) -> None:
    """Ctrl+Shift+G: split the one selected compound body into one body per fixture, selected."""
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
    editor.notify(f"unglued into {len(cmd.bodies)} bodies{cmd.kept_text()} (Ctrl+Z undoes)")
