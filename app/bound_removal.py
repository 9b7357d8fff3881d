"""Removing the bodies that left the world bound: an undoable edit made by the sandbox itself, so
it does not mark the scene unsaved."""
from __future__ import annotations

from .commands import RemoveBodies


class LeftTheBound(RemoveBodies):
    automatic = True

    def __init__(self, app, bodies):
        super().__init__(app, bodies)
        n = len(bodies)
        self.label = f"remove {n} bod{'y' if n == 1 else 'ies'} that left the world bound"


def remove_escapees(app, rd):
    """Remove the moving bodies that crossed the world bound since the last check (one undoable
    edit, with a notice); returns True if any did."""
    gone = app.bound.crossed(rd)
    if not len(gone):
        return False
    gone = set(gone.tolist())
    bodies = [b for b in app.world.bodies if b.id in gone]
    app.editor.execute(LeftTheBound(app.editor, bodies))
    n = len(bodies)
    app.notices.notify(f"{n} bod{'y' if n == 1 else 'ies'} left the world bound and "
                       f"{'was' if n == 1 else 'were'} removed (Ctrl+Z brings {'it' if n == 1 else 'them'} back)")
    return True
