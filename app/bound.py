"""The world bound: a rectangle (m) around the scene.  A moving body (dynamic or kinematic) that
crosses it is removed from the world with a notice, as one undoable edit, so a body that rolls off
the edge or is thrown away is not simulated (and plotted, and fitted) forever.  A body that is
already outside (put there, or brought back by undo) is left alone until it comes back in."""
from __future__ import annotations


import numpy as np

STATIC = 1     # render_data().kind code of a static body


def scene_extent(rd):
    """(lo, hi) of every body's bounding box in render data ``rd``, or None for an empty world."""
    if not len(rd.aabb):
        return None
    box = rd.aabb[np.all(np.isfinite(rd.aabb), axis=1)]
    if not len(box):
        return None
    return box[:, :2].min(0), box[:, 2:].max(0)


def default_bound(extent):
    """The scene's extent grown by max(10 m, half its larger side) on every side and twice that
    above (a body thrown up comes back down), or a 200 m square about the origin."""
    if extent is None:
        return np.array([-100.0, -100.0]), np.array([100.0, 100.0])
    lo, hi = (np.asarray(v, dtype=np.float64) for v in extent)
    m = max(10.0, 0.5 * float(np.max(hi - lo)))
    return lo - m, hi + np.array([m, 2 * m])


class WorldBound:
    """``lo``/``hi``: the corners (m); ``enabled``: remove bodies that cross it; ``shown``: draw it."""

    def __init__(self):
        self.lo = np.array([-100.0, -100.0])
        self.hi = np.array([100.0, 100.0])
        self.enabled = True
        self.shown = True
        self._inside = np.zeros(0, np.int64)     # ids of moving bodies inside at the last check
        # (ids, centres) of the moving bodies' pieces at the last check and the one before
        self._last = self._before = (np.zeros(0, np.int64), np.zeros((0, 2)))

    def fit_scene(self, rd):
        """Set the bound from the scene's extent (on opening a scene, or the View panel's button)."""
        self.lo, self.hi = default_bound(scene_extent(rd))
        self._inside = self.inside_ids(rd)

    def rebase(self, rd):
        """A new world (reset, undo of a whole document): who is inside now, nothing crossed."""
        self._inside = self.inside_ids(rd)

    def set(self, lo, hi):
        """New corners (m); ValueError naming the field if they are not finite or not lo < hi."""
        lo, hi = np.asarray(lo, dtype=np.float64).reshape(2), np.asarray(hi, dtype=np.float64).reshape(2)
        if not (np.all(np.isfinite(lo)) and np.all(np.isfinite(hi))):
            raise ValueError("world bound: the corners must be finite numbers")
        if not np.all(hi > lo):
            raise ValueError(f"world bound: max ({hi[0]:g}, {hi[1]:g}) must be above and right of "
                             f"min ({lo[0]:g}, {lo[1]:g})")
        self.lo, self.hi = lo, hi

    def contains(self, points) -> np.ndarray:
        """Which of the (N, 2) points lie inside the bound."""
        p = np.asarray(points, dtype=np.float64).reshape(-1, 2)
        return np.all((p >= self.lo) & (p <= self.hi), axis=1)

    def inside_ids(self, rd) -> np.ndarray:
        moving = rd.kind != STATIC
        self._last = (rd.ids[moving].astype(np.int64), rd.center[moving].copy())
        return rd.ids[moving & self.contains(rd.center)].astype(np.int64)

    def way_back(self, body_id, rd) -> np.ndarray:
        """How far (m) to move body ``body_id``, which ``crossed`` just found outside, back to
        where it was at the check before, inside (an undo of its removal brings it back there:
        outside, it would fall for ever); (0, 0) if it was not seen then."""
        ids, centres = self._before
        was, now = np.nonzero(ids == body_id)[0], np.nonzero(rd.ids == body_id)[0]
        if not len(was) or not len(now):
            return np.zeros(2)
        return centres[was[0]] - rd.center[now[0]]

    def crossed(self, rd) -> np.ndarray:
        """Ids of moving bodies inside at the last check and outside now (their centre crossed
        the bound); remembers who is inside now for the next check."""
        self._before = self._last           # where they were at the last check (way_back)
        inside = self.inside_ids(rd)
        out = np.zeros(0, np.int64)
        if self.enabled and len(self._inside):
            present = rd.ids[rd.kind != STATIC]
            out = self._inside[np.isin(self._inside, present) & ~np.isin(self._inside, inside)]
        self._inside = inside
        return out

    def content(self, rd):
        """(lo, hi) of the bodies whose centre is inside the bound (what F frames), or None."""
        keep = self.contains(rd.center)
        if not np.any(keep):
            return scene_extent(rd)
        box = rd.aabb[keep]
        box = box[np.all(np.isfinite(box), axis=1)]
        return (box[:, :2].min(0), box[:, 2:].max(0)) if len(box) else None

    def outline(self):
        """The four edges as (p0, p1) pairs (m) for drawing."""
        (x0, y0), (x1, y1) = self.lo, self.hi
        c = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        return [(c[i], c[(i + 1) % 4]) for i in range(4)]

    def describe(self) -> str:
        (x0, y0), (x1, y1) = self.lo, self.hi
        return f"x {x0:.4g} .. {x1:.4g} m, y {y0:.4g} .. {y1:.4g} m"


