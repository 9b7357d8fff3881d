"""World's springs: adding and removing them, names (a part of World)."""
from __future__ import annotations

import numpy as np

from .body import Body
from .spring import Spring
from .validate import finite_num, finite_vec, shown


class SpringsMixin:
    """The spring half of :class:`~physics.World` (see world.py for the state it uses)."""

    # -- springs ----------------------------------------------------------
    def add_spring(self, body_a: Body, body_b: Body | None = None, anchor_a=(0.0, 0.0), anchor_b=(0.0, 0.0),
                   stiffness: float = 100.0, damping: float = 0.0, rest_length: float | None = None,
                   name: str | None = None) -> Spring:
        """A damped spring from ``anchor_a`` on ``body_a`` (body coordinates) to ``anchor_b`` on
        ``body_b``, or to the world point ``anchor_b`` when ``body_b`` is None.  The rest length
        defaults to the current distance between the anchors."""
        self._check_editable("add_spring")
        for b, field in ((body_a, "body_a"), (body_b, "body_b")):
            if b is None and field == "body_b":
                continue
            if not isinstance(b, Body) or b.world is not self or not b.alive:
                raise ValueError(f"{field}: expected a live body of this world, got {shown(b)}")
        if body_a is body_b:
            raise ValueError("body_b: a spring needs two different bodies (or None for a world anchor)")
        la = finite_vec(anchor_a, "anchor_a")
        lb = finite_vec(anchor_b, "anchor_b")
        k = finite_num(stiffness, "stiffness", lo=0.0)
        c = finite_num(damping, "damping", lo=0.0)
        if name is not None:
            self._spring_names.check_new(name)
        pa = np.array(body_a.local_to_world(la))
        pb = lb if body_b is None else np.array(body_b.local_to_world(lb))
        rest = float(np.hypot(*(pa - pb))) if rest_length is None else finite_num(rest_length, "rest_length", lo=0.0)
        oid, s = self._springs.add()
        S = self._springs.view
        B = self._bodies.view
        S.a[s] = body_a._s
        S.b[s] = -1 if body_b is None else body_b._s
        S.la[s] = la - B.com[body_a._s]
        S.lb[s] = lb if body_b is None else lb - B.com[body_b._s]
        S.k[s], S.c[s], S.rest[s] = k, c, rest
        h = Spring(self, oid, body_a, body_b)
        self._spring_handles[oid] = h
        self._spring_names.add(oid, name)
        self._touched(body_a._s)
        if body_b is not None:
            self._touched(body_b._s)
        self._pipeline.invalidate()
        return h

    def _remove_spring(self, sp: Spring) -> None:
        if sp._world is not self or not sp.alive:
            raise ValueError(f"remove: {shown(sp)} is not a live spring of this world")
        if sp.body_a.alive:
            self._touched(sp.body_a._s)
        if sp.body_b is not None and sp.body_b.alive:
            self._touched(sp.body_b._s)
        self._springs.remove(sp.id)
        del self._spring_handles[sp.id]
        self._spring_names.drop(sp.id)
        self._pipeline.invalidate()

    def spring(self, name: str) -> Spring:
        """The spring called ``name`` (KeyError if there is none)."""
        return self._spring_handles[self._spring_names.id_of(name)]

    @property
    def springs(self) -> list[Spring]:
        """Every spring of the world, in slot order (a new list each call)."""
        ids = self._springs.view.id[: self._springs.n]
        return [self._spring_handles[int(i)] for i in ids]

    def _name_of_spring(self, oid):
        return self._spring_names.name_of(oid)

    def _rename_spring(self, oid, name):
        self._spring_names.rename(oid, name)
