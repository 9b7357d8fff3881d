"""The laser tool's undoable edits: place, remove, re-aim and move a laser (``app.lasers``).  Like the
other commands, ``app`` is the :class:`app.editor.Editor`; a laser on a body refers to it through
its Ref, so a body deleted and brought back by undo still carries its laser."""
from __future__ import annotations

from .commands import Command
from .lasers import Laser


class AddLaser(Command):
    """Place a laser made from ``spec`` (``Laser.spec()``'s keys)."""

    def __init__(self, spec: dict):
        self.laser = Laser(spec["ref"], spec["local"], spec["angle"], spec.get("index"))
        self.label = "place laser"

    def do(self, app):
        app.lasers.items.append(self.laser)

    def undo(self, app):
        app.lasers.items.remove(self.laser)
        if app.tools["laser"].selected is self.laser:
            app.tools["laser"].selected = None


class RemoveLaser(Command):
    """Delete ``laser`` (undo puts it back in its place in the list)."""

    def __init__(self, laser):
        self.laser = laser
        self.place = 0
        self.label = "delete laser"

    def do(self, app):
        self.place = app.lasers.items.index(self.laser)
        app.lasers.items.remove(self.laser)
        if app.tools["laser"].selected is self.laser:
            app.tools["laser"].selected = None

    def undo(self, app):
        app.lasers.items.insert(self.place, self.laser)


class AimLaser(Command):
    """Point ``laser`` along ``angle`` (rad, in its body's frame or the world's)."""

    def __init__(self, laser, angle, old):
        self.laser, self.angle, self.old = laser, float(angle), float(old)
        self.label = "aim laser"

    def do(self, app):
        self.laser.angle = self.angle

    def undo(self, app):
        self.laser.angle = self.old


class MoveLaser(Command):
    """Put ``laser`` where ``spec`` says (``Laser.spec()``'s keys: its body, point and angle)."""

    def __init__(self, laser, spec, old):
        self.laser, self.spec, self.old = laser, dict(spec), dict(old)
        self.label = "move laser"

    def do(self, app):
        self.laser.set_spec(self.spec)

    def undo(self, app):
        self.laser.set_spec(self.old)
