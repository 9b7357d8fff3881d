"""Move and rotate handles of the selected bodies (select tool): a square at the centre of
their bounding box moves them all (two or more bodies), a disc above the box rotates them all
about that centre.  Grid and angle snapping apply; the whole drag is one undoable edit."""
from __future__ import annotations

import math

import numpy as np

from ..clipboard import selected_bodies
from ..commands import Group, SetProperty
from .world_pins import pin_commands

HANDLE_PX = 9.0          # grab radius of a handle (px)
ROTATE_PX = 30.0         # the rotate handle's distance above the box (px)
COLOR = (1.0, 0.82, 0.45, 0.95)
FRAME = (1.0, 0.82, 0.45, 0.45)


class Handles:
    def __init__(self, editor):
        self.editor = editor
        self.active = None       # ("move" | "rotate", pivot, start point/angle, [(ref, pos0, angle0)])

    def frame(self):
        """(bodies, box lo, box hi, centre, rotate handle) of the selection, or None."""
        ed = self.editor
        bodies = selected_bodies(ed.selection)
        if not bodies:
            return None
        rd = ed.world.render_data()
        mask = np.isin(rd.ids, np.array([b.id for b in bodies], dtype=np.int64))
        if not np.any(mask):
            return None
        box = rd.aabb[mask]
        lo, hi = box[:, :2].min(0), box[:, 2:].max(0)
        centre = 0.5 * (lo + hi)
        knob = np.array([centre[0], hi[1] + ROTATE_PX / ed.camera.scale])
        return bodies, lo, hi, centre, knob

    def hit(self, p):
        """Which handle is under world point ``p``: "move", "rotate" or None."""
        f = self.frame()
        if f is None:
            return None
        bodies, _, _, centre, knob = f
        px = self.editor.camera.scale
        p = np.asarray(p, dtype=np.float64)
        if np.hypot(*(p - knob)) * px <= HANDLE_PX:
            return "rotate"
        if len(bodies) >= 2 and np.hypot(*(p - centre)) * px <= HANDLE_PX:
            return "move"
        return None

    def press(self, p, kind):
        bodies, _, _, centre, _ = self.frame()
        p = np.asarray(p, dtype=np.float64)
        start = math.atan2(*(p - centre)[::-1]) if kind == "rotate" else p
        refs = self.editor.refs
        self.active = (kind, centre, start, [(refs.of(b), np.array(b.position), b.angle) for b in bodies])

    def drag(self, p):
        """Move or rotate every body from where it was at the press (snapped while snapping)."""
        if self.active is None:
            return
        kind, pivot, start, items = self.active
        snap = self.editor.snap
        p = np.asarray(p, dtype=np.float64)
        if kind == "move":
            off = snap.point(p - start)
            for ref, pos0, _ in items:
                if ref.obj.alive:
                    ref.obj.position = tuple(pos0 + off)
            return
        a = snap.rotation(math.atan2(*(p - pivot)[::-1]) - start)
        c, s = math.cos(a), math.sin(a)
        for ref, pos0, ang0 in items:
            if ref.obj.alive:
                d = pos0 - pivot
                ref.obj.position = (pivot[0] + c * d[0] - s * d[1], pivot[1] + s * d[0] + c * d[1])
                ref.obj.angle = ang0 + a

    def release(self):
        """One undoable edit for the whole drag (nothing if nothing moved)."""
        if self.active is None:
            return
        kind, _, _, items = self.active
        self.active = None
        ed = self.editor
        cmds = []
        moved = []
        for ref, pos0, ang0 in items:
            b = ref.obj
            if not b.alive:
                continue
            if not np.allclose(b.position, pos0, atol=0, rtol=0):
                cmds.append(SetProperty(ed, b, "position", b.position, old=tuple(pos0)))
            if kind == "rotate" and b.angle != ang0:
                cmds.append(SetProperty(ed, b, "angle", b.angle, old=ang0))
            moved.append((b, pos0, ang0))
        if cmds:
            cmds += pin_commands(ed, [b for b, _, _ in moved], rigid_move(*moved[0]))
            ed.execute(Group(cmds, f"{kind} {len(items)} bod{'y' if len(items) == 1 else 'ies'}"))

    def cancel(self):
        """Put the bodies back where the drag started."""
        if self.active is not None:
            for ref, pos0, ang0 in self.active[3]:
                if ref.obj.alive:
                    ref.obj.position, ref.obj.angle = tuple(pos0), ang0
        self.active = None

    def decorate(self, decor):
        f = self.frame()
        if f is None:
            return
        bodies, lo, hi, centre, knob = f
        corners = [lo, (hi[0], lo[1]), hi, (lo[0], hi[1])]
        for i in range(4):
            decor.segments.append((corners[i], corners[(i + 1) % 4], 1.0, FRAME))
        decor.segments.append(((centre[0], hi[1]), knob, 1.0, FRAME))
        decor.points.append((knob, 6.0, COLOR))
        if len(bodies) >= 2:
            decor.points.append((centre, 6.0, COLOR))


def rigid_move(body, pos0, ang0):
    """The motion (a function of a world point) that took ``body`` from ``pos0``/``ang0`` to where
    it is: the handles move and turn every selected body alike."""
    a = body.angle - ang0
    c, s = math.cos(a), math.sin(a)
    rot = np.array([[c, -s], [s, c]])
    p0, p1 = np.asarray(pos0, dtype=np.float64), np.asarray(body.position, dtype=np.float64)
    return lambda p: p1 + rot @ (p - p0)
