"""Removing the bodies that left the world bound: an undoable edit made by the sandbox itself, so
it does not mark the scene unsaved, and its undo brings each body back inside, at rest."""
from __future__ import annotations

from .commands import RemoveBodies


class LeftTheBound(RemoveBodies):
    """``shifts``: body id -> how far (m) back inside each body was at the check before."""

    automatic = True

    def __init__(self, app, bodies, shifts):
        super().__init__(app, bodies)
        n = len(bodies)
        self.label = f"remove {n} bod{'y' if n == 1 else 'ies'} that left the world bound"
        self._shifts = [tuple(shifts.get(b.id, (0.0, 0.0))) for b in bodies]

    def do(self, app):
        super().do(app)
        if self._shifts is None:      # a redo: the bodies were already brought back inside
            return
        for spec, (dx, dy) in zip(self.specs, self._shifts):
            x, y = spec["position"]
            spec.update(position=(x + dx, y + dy), velocity=(0.0, 0.0), angular_velocity=0.0)
        self._shifts = None


def remove_escapees(app, rd):
    """Remove the moving bodies that crossed the world bound since the last check (one undoable
    edit, with a notice); returns True if any did."""
    gone = app.bound.crossed(rd)
    if not len(gone):
        return False
    shifts = {int(i): app.bound.way_back(int(i), rd) for i in gone}
    bodies = [b for b in app.world.bodies if b.id in shifts]
    app.editor.execute(LeftTheBound(app.editor, bodies, shifts))
    n = len(bodies)
    app.notices.notify(f"{n} bod{'y' if n == 1 else 'ies'} left the world bound and "
                       f"{'was' if n == 1 else 'were'} removed (Ctrl+Z brings {'it' if n == 1 else 'them'} back "
                       "inside)")
    return True
