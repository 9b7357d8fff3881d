"""Laser tool: click to place an emitter (on a body it rides with the body, in empty space it is
fixed), drag to aim it.  Drag an emitter to re-aim it, Ctrl+drag it to move it (dropped on a body
it rides with that body), shift-click it to delete it; a click on an emitter selects it (the
inspector reads its beam out) and Delete removes it.  The beam itself is ``app.lasers``'."""
from __future__ import annotations

import numpy as np

from ..laser_commands import AddLaser, AimLaser, MoveLaser, RemoveLaser
from ..lasers import COLOR, Laser, aim_angle, moved_spec, trace
from ..picking import body_at
from .base import Tool

GRAB_PX = 9.0        # an emitter within this many pixels of a click is picked, not a new one placed
AIM_PX = 6.0         # a drag shorter than this is a click (a new emitter keeps its default aim)


class LaserTool(Tool):
    name = "laser"
    snaps = True
    help = "click: place a laser (on a body it rides with it), drag to aim; drag an emitter to re-aim, " \
           "Ctrl+drag it to move it, shift-click it (or select it and press Delete) to remove it"

    def __init__(self, editor):
        super().__init__(editor)
        self.selected = None         # the emitter picked last (Delete removes it)
        self.pending = None          # the laser being placed (not yet in the document)
        self.aiming = None           # (laser, old angle) while an emitter is dragged
        self.moving = None           # (laser, old spec) while an emitter is Ctrl+dragged
        self.p0 = None

    def press(self, p, button, mods):
        from pyglet.window import key as K
        ed = self.editor
        self.p0 = np.array(p, dtype=float)
        hit = ed.lasers.near(p, GRAB_PX / ed.camera.scale)
        if hit is not None:
            if mods & K.MOD_SHIFT:
                ed.execute(RemoveLaser(hit))
                ed.notify("laser deleted (Ctrl+Z brings it back)")
                return
            ed.select(None)           # the inspector shows the emitter, not a body selected before
            self.selected = hit
            if mods & (K.MOD_CTRL | K.MOD_COMMAND):
                self.moving = (hit, hit.spec())
            else:
                self.aiming = (hit, hit.angle)
            return
        b = body_at(ed.world, p)
        if b is None:
            self.pending = Laser(None, p, 0.0)
        else:
            index = next((k for k, x in enumerate(ed.world.bodies) if x.id == b.id), None)
            self.pending = Laser(ed.refs.of(b), b.world_to_local(tuple(p)), aim_angle(b, (1.0, 0.0)), index)

    def _aim(self, laser, p) -> bool:
        d = np.asarray(p, dtype=float) - self.p0
        if np.hypot(*d) * self.editor.camera.scale < AIM_PX:
            return False
        laser.angle = aim_angle(laser.body(), d)
        return True

    def _move(self, p):
        """The Ctrl+dragged emitter at ``p`` (its beam follows), or back where it was for a click."""
        lz, old = self.moving
        if np.hypot(*(np.asarray(p, dtype=float) - self.p0)) * self.editor.camera.scale < AIM_PX:
            lz.set_spec(old)
        else:
            lz.set_spec(moved_spec(self.editor.world, self.editor.refs, lz, p))

    def drag(self, p):
        if self.pending is not None:
            self._aim(self.pending, p)
        elif self.aiming is not None:
            self._aim(self.aiming[0], p)
        elif self.moving is not None:
            self._move(p)

    def release(self, p):
        ed = self.editor
        if self.pending is not None:
            lz, self.pending = self.pending, None
            self._aim(lz, p)
            cmd = AddLaser(lz.spec())
            ed.execute(cmd)
            ed.select(None)
            self.selected = cmd.laser
            where = "fixed in the world" if lz.ref is None else f"on {lz.ref.obj.name or lz.ref.obj.id}"
            ed.notify(f"laser placed {where}")
        elif self.aiming is not None:
            lz, old = self.aiming
            self.aiming = None
            if self._aim(lz, p) and lz.angle != old:
                new, lz.angle = lz.angle, old
                ed.execute(AimLaser(lz, new, old))
        elif self.moving is not None:
            self._move(p)
            (lz, old), self.moving = self.moving, None
            new = lz.spec()
            if new != old:
                lz.set_spec(old)
                ed.execute(MoveLaser(lz, new, old))

    def key(self, symbol) -> bool:
        from pyglet.window import key as K
        if symbol in (K.DELETE, K.BACKSPACE) and self.selected is not None \
                and self.selected in self.editor.lasers.items:
            self.editor.execute(RemoveLaser(self.selected))
            self.editor.notify("laser deleted (Ctrl+Z brings it back)")
            return True
        return False

    def cancel(self):
        self.pending = None
        if self.aiming is not None:
            lz, old = self.aiming
            lz.angle = old
            self.aiming = None
        if self.moving is not None:
            lz, old = self.moving
            lz.set_spec(old)
            self.moving = None

    def decorate(self, decor, cursor):
        lz = self.pending
        if lz is None:
            return
        p, d = lz.origin_direction()
        pts = trace(self.editor.world, p, d, lz.body())
        for a, b in zip(pts[:-1], pts[1:]):
            decor.segments.append((a, b, 1.5, (*COLOR[:3], 0.6)))
        decor.points.append((p, 5.0, (1.0, 0.55, 0.55, 1.0)))
