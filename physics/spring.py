"""Spring handles: damped springs between two bodies or a body and a world point."""
from __future__ import annotations

import numpy as np

from .validate import finite_num, finite_vec


class Spring:
    """Handle of one spring (Hooke's law plus a damper along its axis, seed eqs. 18-20)."""

    __slots__ = ("_world", "_id", "_a", "_b")

    def __init__(self, world, oid: int, body_a, body_b):
        self._world = world
        self._id = oid
        self._a = body_a
        self._b = body_b

    @property
    def body_a(self):
        """The body the spring's anchor_a is on (read-only: a spring keeps its bodies)."""
        return self._a

    @property
    def body_b(self):
        """The body of anchor_b, or None when anchor_b is a fixed world point (read-only)."""
        return self._b

    @property
    def _s(self) -> int:
        try:
            return self._world._springs.slot_of[self._id]
        except KeyError:
            raise ValueError(f"spring {self._id} was removed from its world") from None

    @property
    def _S(self):
        return self._world._springs.view

    @property
    def id(self) -> int:
        """Stable integer id of this spring (never reused in its world)."""
        return self._id

    @property
    def alive(self) -> bool:
        """False once the spring (or a body it joins) was removed from the world."""
        return self._id in self._world._springs.slot_of

    @property
    def anchor_a(self) -> tuple[float, float]:
        """Attachment on body a, in a's body coordinates."""
        p = self._S.la[self._s] + self.body_a._B.com[self.body_a._s]
        return (float(p[0]), float(p[1]))

    @anchor_a.setter
    def anchor_a(self, value):
        self._S.la[self._s] = finite_vec(value, "anchor_a") - self.body_a._B.com[self.body_a._s]
        self._world._touched(self.body_a._s)

    @property
    def anchor_b(self) -> tuple[float, float]:
        """Attachment on body b (b's body coordinates), or the world point when b is None."""
        p = self._S.lb[self._s]
        if self.body_b is not None:
            p = p + self.body_b._B.com[self.body_b._s]
        return (float(p[0]), float(p[1]))

    @anchor_b.setter
    def anchor_b(self, value):
        v = finite_vec(value, "anchor_b")
        if self.body_b is not None:
            v = v - self.body_b._B.com[self.body_b._s]
        self._S.lb[self._s] = v
        self._world._touched(self.body_a._s)

    @property
    def stiffness(self) -> float:
        """Spring constant k in N/m (>= 0). ValueError for negative or non-finite values."""
        return float(self._S.k[self._s])

    @stiffness.setter
    def stiffness(self, value):
        self._S.k[self._s] = finite_num(value, "stiffness", lo=0.0)
        self._world._touched(self.body_a._s)

    @property
    def damping(self) -> float:
        """Damping coefficient c in N s/m along the spring's axis (>= 0). ValueError for negative or non-finite values."""
        return float(self._S.c[self._s])

    @damping.setter
    def damping(self, value):
        self._S.c[self._s] = finite_num(value, "damping", lo=0.0)
        self._world._touched(self.body_a._s)

    @property
    def rest_length(self) -> float:
        """Length (m, >= 0) at which the spring exerts no force. ValueError for negative or non-finite values."""
        return float(self._S.rest[self._s])

    @rest_length.setter
    def rest_length(self, value):
        self._S.rest[self._s] = finite_num(value, "rest_length", lo=0.0)
        self._world._touched(self.body_a._s)

    @property
    def name(self):
        """Optional unique name (str or None); world.spring(name) finds it. ValueError when another spring has it."""
        return self._world._name_of_spring(self._id)

    @name.setter
    def name(self, value):
        self._world._rename_spring(self._id, value)

    def endpoints(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """World positions of both attachment points."""
        pa = self.body_a.local_to_world(self.anchor_a)
        pb = self.anchor_b if self.body_b is None else self.body_b.local_to_world(self.anchor_b)
        return pa, pb

    @property
    def length(self) -> float:
        """Current distance (m) between the two attachment points."""
        pa, pb = self.endpoints()
        return float(np.hypot(pa[0] - pb[0], pa[1] - pb[1]))

    def __repr__(self):
        b = self.body_b.name if self.body_b is not None else "world"
        return f"<Spring {self.name or self._id}: {self.body_a.name} - {b} k={self.stiffness:g}>"
