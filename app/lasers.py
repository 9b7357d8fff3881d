"""Lasers (issue 15): an emitter fixed in the world or riding on a body, its beam traced every
frame to the first fixture it meets and mirrored off it (about the hit normal) for up to
``MAX_SEGMENTS`` segments, as Algodoo's laser.  The lasers belong to the editing session's
document: the laser tool's edits are undoable commands (``app.laser_commands``); a reset keeps
them (an emitter on a body follows the body at its place in the reset world), opening another
scene brings that scene's.  They are saved in the scene file's ``sandbox`` section, which the
loader leaves in ``world.metadata["lasers"]`` (docs/scene-format.md)."""
from __future__ import annotations

import math

import numpy as np

MAX_SEGMENTS = 8        # beam segments: the first one and up to seven reflections
REACH = 200.0           # m: how far a segment looks for a fixture (beyond: it ends in the air)
EPS = 1e-6              # m: a reflected segment starts this far off the surface it left
COLOR = (1.0, 0.18, 0.22, 0.95)
EMITTER_PX = 5.0


class Laser:
    """An emitter at ``local`` (m, in the frame of the body behind ``ref``; world coordinates when
    ``ref`` is None) shooting along ``angle`` (rad, in the same frame).  ``index`` is the body's
    place in world.bodies (found again after a reset)."""

    def __init__(self, ref, local, angle, index=None):
        self.ref = ref
        self.local = (float(local[0]), float(local[1]))
        self.angle = float(angle)
        self.index = index
        self.path = np.zeros((0, 2))     # the beam's points, emitter first (traced each frame)
        self.hits: list = []             # the bodies its segments end on, in turn (traced with it)

    def body(self):
        """The live body the emitter rides on, or None (fixed, or its body is deleted)."""
        b = None if self.ref is None else self.ref.obj
        return b if b is not None and b.alive else None

    @property
    def shown(self) -> bool:
        """False while the body it rides on is deleted (an undo brings both back)."""
        return self.ref is None or self.body() is not None

    def origin_direction(self):
        """(world point, world unit direction) of the emitter now."""
        b = self.body()
        d = (math.cos(self.angle), math.sin(self.angle))
        if b is None:
            return np.array(self.local), np.array(d)
        c, s = math.cos(b.angle), math.sin(b.angle)
        return np.array(b.local_to_world(self.local)), np.array((c * d[0] - s * d[1], s * d[0] + c * d[1]))

    def spec(self) -> dict:
        """What a command needs to make this laser again."""
        return {"ref": self.ref, "local": self.local, "angle": self.angle, "index": self.index}

    def set_spec(self, spec: dict):
        self.ref, self.local, self.angle, self.index = spec["ref"], spec["local"], spec["angle"], spec["index"]

    def readout(self) -> dict:
        """What the inspector says of the beam as last traced: its length up to its last hit (m),
        its bounces (the points it was mirrored at), the bodies it meets in turn, and whether it
        ends in the open (rather than on a surface)."""
        pts = self.path
        n_hit = len(self.hits)
        length = float(np.sum(np.hypot(*np.diff(pts[:n_hit + 1], axis=0).T))) if n_hit else 0.0
        return {"length": length, "bounces": max(len(pts) - 2, 0), "hits": list(self.hits),
                "open": len(pts) > n_hit + 1}


def moved_spec(world, refs, laser, p) -> dict:
    """``laser`` moved to world point ``p``, pointing the same way: it rides on the body there (the
    first body under ``p``) or is fixed in the world when there is none."""
    from .picking import body_at
    _, d = laser.origin_direction()
    try:
        b = body_at(world, tuple(p))
    except ValueError:
        b = None
    if b is None:
        return {"ref": None, "local": (float(p[0]), float(p[1])), "angle": aim_angle(None, d), "index": None}
    index = next((k for k, x in enumerate(world.bodies) if x.id == b.id), None)
    return {"ref": refs.of(b), "local": tuple(b.world_to_local(tuple(p))), "angle": aim_angle(b, d), "index": index}


def aim_angle(body, direction) -> float:
    """The emitter angle (in ``body``'s frame, or the world's for None) of world ``direction``."""
    a = math.atan2(direction[1], direction[0])
    return a - body.angle if body is not None else a


def reflect(d, n):
    """Mirror direction ``d`` about the surface with unit normal ``n``."""
    return d - 2.0 * float(np.dot(d, n)) * n


def trace(world, origin, direction, skip_body=None, segments=MAX_SEGMENTS, reach=REACH):
    """The beam's points: ``trace_hits``' first part."""
    return trace_hits(world, origin, direction, skip_body, segments, reach)[0]


def trace_hits(world, origin, direction, skip_body=None, segments=MAX_SEGMENTS, reach=REACH):
    """The beam from ``origin`` along unit ``direction``: its points (K + 1, 2) for K <= ``segments``
    segments, and the bodies its segments end on (one a segment that meets a fixture).  Each segment ends at the first fixture it meets (its outward normal mirrors the
    beam) or after ``reach`` metres in the air; the first segment passes through ``skip_body``
    (the emitter's own body: an emitter inside it shines out of it).  A beam that starts inside
    a fixture (normal (0, 0)) stops there."""
    p = np.asarray(origin, dtype=np.float64)
    d = np.asarray(direction, dtype=np.float64)
    pts, bodies = [p], []
    for k in range(segments):
        end = p + reach * d
        hit = _first_hit(world, p, end, skip_body if k == 0 else None)
        if hit is None:
            pts.append(end)
            break
        q = np.array(hit.point)
        pts.append(q)
        bodies.append(hit.body)
        n = np.array(hit.normal)
        if not n.any():
            break
        d = reflect(d, n)
        p = q + EPS * n
    return np.array(pts), bodies


def _first_hit(world, p, end, skip_body):
    if skip_body is None:
        hits = world.ray_cast(tuple(p), tuple(end), first=True)
        return hits[0] if hits else None
    for h in world.ray_cast(tuple(p), tuple(end)):
        if h.body.id != skip_body.id:
            return h
    return None


class Lasers:
    """The lasers of the open document, and their beams this frame."""

    def __init__(self):
        self.items: list[Laser] = []

    def visible(self):
        return [lz for lz in self.items if lz.shown]

    def update(self, world):
        """Trace every shown laser's beam in ``world`` as it stands."""
        for lz in self.items:
            if lz.shown:
                p, d = lz.origin_direction()
                lz.path, lz.hits = trace_hits(world, p, d, lz.body())
            else:
                lz.path, lz.hits = np.zeros((0, 2)), []

    def near(self, p, radius):
        """The shown laser whose emitter is nearest world point ``p`` within ``radius`` m, or None."""
        best, bd = None, radius
        for lz in self.visible():
            dist = float(np.hypot(*(lz.origin_direction()[0] - np.asarray(p))))
            if dist <= bd:
                best, bd = lz, dist
        return best

    def reset(self, world, refs, keep=True):
        """A reset (``keep``): each laser on a body follows the body at its place in the new world
        (fixed lasers stay).  A new document (not ``keep``): the lasers its file has."""
        if not keep:
            self.from_metadata(world, refs)
            return
        for lz in self.items:
            if lz.ref is not None and lz.index is not None and lz.index < len(world.bodies):
                lz.ref = refs.of(world.bodies[lz.index])

    def to_metadata(self, world):
        """Put the lasers where the scene saver reads them (those on deleted bodies are left out)."""
        out = [{"body": None if lz.ref is None else lz.body().id, "point": lz.local, "angle": lz.angle}
               for lz in self.items if lz.shown]
        if out:
            world.metadata["lasers"] = out
        else:
            world.metadata.pop("lasers", None)

    def from_metadata(self, world, refs):
        """The lasers of a scene as loaded (``world.metadata["lasers"]``, by body id)."""
        place = {b.id: (k, b) for k, b in enumerate(world.bodies)}
        self.items = []
        for it in world.metadata.get("lasers", []):
            k, b = place.get(it["body"], (None, None))
            if it["body"] is None or b is not None:
                self.items.append(Laser(None if b is None else refs.of(b), it["point"], it["angle"], k))

    def decorate(self, decor, selected=None, width=2.0):
        """The beams as segments and the emitters as points (``selected`` drawn larger)."""
        for lz in self.visible():
            pts = lz.path
            for a, b in zip(pts[:-1], pts[1:]):
                decor.segments.append((a, b, width, COLOR))
            if len(pts):
                r = EMITTER_PX * (1.6 if lz is selected else 1.0)
                decor.points.append((pts[0], r, (1.0, 0.55, 0.55, 1.0)))

    def describe(self) -> list:
        """For the status file: each laser's body id (None: fixed), local point, angle and beam."""
        out = []
        for lz in self.items:
            r = lz.readout()
            out.append({"body": None if lz.ref is None or lz.ref.obj is None else lz.ref.obj.id,
                        "local": list(lz.local), "angle": lz.angle, "shown": lz.shown, "path": lz.path.tolist(),
                        "length": r["length"], "bounces": r["bounces"], "hits": [b.id for b in r["hits"]],
                        "open": r["open"]})
        return out
