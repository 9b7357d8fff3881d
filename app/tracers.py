"""Tracers: a trail behind a point of a body, the last ``seconds`` of world time of where that
point went, drawn as a line fading towards its oldest end.  Trails are cleared on reset (the
tracers then follow the reset world's bodies); a new document brings the tracers its file has
(the scene's ``sandbox`` section, left by the loader in ``world.metadata["tracers"]``)."""
from __future__ import annotations

import numpy as np

#: trail colours, cycled per tracer (bright against the dark background and the blue bodies)
TRAIL_COLORS = ((1.0, 0.35, 0.75), (0.35, 1.0, 0.85), (1.0, 0.9, 0.3), (0.7, 0.55, 1.0))
CAP = 2400            # points kept per trail at most (40 s at 60 Hz)


class Tracer:
    """A point ``local`` (m, in the body's frame) of the body behind ``ref``; ``index`` is the
    body's place in world.bodies (found again after a reset); ``points``/``times`` the trail."""

    def __init__(self, ref, local, color, index):
        self.ref = ref
        self.local = tuple(map(float, local))
        self.color = color
        self.index = index
        self.points = np.zeros((CAP, 2))
        self.times = np.zeros(CAP)
        self.n = 0

    def trail(self):
        """(points (K, 2), times (K,)) oldest first."""
        return self.points[:self.n], self.times[:self.n]

    def append(self, t, p, seconds):
        """Add point ``p`` at world time ``t``; drop the points older than ``t - seconds``."""
        if self.n == CAP:
            self.points[:-1], self.times[:-1] = self.points[1:], self.times[1:]
            self.n -= 1
        self.points[self.n], self.times[self.n] = p, t
        self.n += 1
        old = int(np.searchsorted(self.times[:self.n], t - seconds, side="left"))
        if old:
            keep = self.n - old
            self.points[:keep], self.times[:keep] = self.points[old:self.n], self.times[old:self.n]
            self.n = keep

    def clear(self):
        self.n = 0


class Tracers:
    """The tracers of the open scene; ``seconds`` (s, > 0) of trail kept."""

    def __init__(self, seconds: float = 3.0):
        self.items: list[Tracer] = []
        self.seconds = seconds
        self._last_time = None

    def set_seconds(self, seconds):
        """Trail length in world seconds, in (0, 60]; ValueError names the field otherwise."""
        if not (isinstance(seconds, (int, float)) and 0 < seconds <= 60):
            raise ValueError(f"trail seconds: must be in (0, 60] s, got {seconds!r}")
        self.seconds = float(seconds)

    def add(self, body, point, refs, world):
        """A tracer at world ``point`` of ``body`` (its trail starts now)."""
        index = next((k for k, b in enumerate(world.bodies) if b.id == body.id), 0)
        color = TRAIL_COLORS[len(self.items) % len(TRAIL_COLORS)]
        tr = Tracer(refs.of(body), body.world_to_local(tuple(point)), color, index)
        self.items.append(tr)
        return tr

    def remove_body(self, body, refs) -> int:
        """Remove the tracers of ``body``; returns how many."""
        ref = refs.of(body)
        n = len(self.items)
        self.items = [t for t in self.items if t.ref is not ref]
        return n - len(self.items)

    def sample(self, world):
        """Add every live tracer's point if world time moved since the last sample."""
        if not self.items or world.time == self._last_time:
            return
        self._last_time = world.time
        for tr in self.items:
            b = tr.ref.obj
            if b is not None and b.alive:
                tr.append(world.time, b.local_to_world(tr.local), self.seconds)

    def reset(self, world, refs, keep=True):
        """A reset (``keep``): trails cleared, each tracer follows the body at its place in the
        new world.  A new document (not ``keep``): the tracers its file has."""
        self._last_time = None
        if not keep:
            self.from_metadata(world, refs)
            return
        for tr in self.items:
            tr.clear()
            if tr.index < len(world.bodies):
                tr.ref = refs.of(world.bodies[tr.index])

    def to_metadata(self, world):
        """Put the tracers where the scene saver reads them (those of deleted bodies are left out)."""
        out = [{"body": tr.ref.obj.id, "point": tr.local} for tr in self.items
               if tr.ref.obj is not None and tr.ref.obj.alive]
        if out:
            world.metadata["tracers"] = out
        else:
            world.metadata.pop("tracers", None)

    def from_metadata(self, world, refs):
        """The tracers of a scene as loaded (``world.metadata["tracers"]``, by body id)."""
        place = {b.id: (k, b) for k, b in enumerate(world.bodies)}
        self.items = []
        for it in world.metadata.get("tracers", []):
            if it["body"] in place:
                k, b = place[it["body"]]
                color = TRAIL_COLORS[len(self.items) % len(TRAIL_COLORS)]
                self.items.append(Tracer(refs.of(b), it["point"], color, k))

    def segments(self):
        """Every trail as line segments (p0 (K, 2), p1 (K, 2), rgba (K, 4)), alpha fading from
        0.9 at the newest point to 0 at the oldest."""
        p0, p1, col = [], [], []
        for tr in self.items:
            pts, _ = tr.trail()
            k = len(pts) - 1
            if k < 1:
                continue
            p0.append(pts[:-1])
            p1.append(pts[1:])
            c = np.empty((k, 4))
            c[:, :3] = tr.color
            c[:, 3] = 0.9 * np.linspace(0.0, 1.0, k + 1)[1:]
            col.append(c)
        if not p0:
            return None
        return np.concatenate(p0), np.concatenate(p1), np.concatenate(col)
