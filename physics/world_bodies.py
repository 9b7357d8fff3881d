"""World's bodies: adding, reshaping and removing them, names, waking (a part of World)."""
from __future__ import annotations

import math

import numpy as np

from .body import Body
from .geometry.shapes import Circle, Polygon, Shape
from .spring import Spring
from .store import CIRCLE, DYNAMIC, KINDS, POLYGON, STATIC
from .validate import checked_density, finite_num, finite_vec, friction_pair, shown


class BodiesMixin:
    """The body half of :class:`~physics.World` (see world.py for the state it uses)."""

    # -- bodies -----------------------------------------------------------
    def add_body(self, shape: Shape, kind: str = "dynamic", position=(0.0, 0.0), angle: float = 0.0,
                 velocity=(0.0, 0.0), angular_velocity: float = 0.0, density: float = 1.0,
                 restitution: float = 0.0, friction=0.6, name: str | None = None) -> Body:
        """Add a body; every argument is validated and a ValueError names the bad field."""
        if not isinstance(shape, Shape):
            raise ValueError(f"shape: expected a physics.Polygon or physics.Circle, got {type(shape).__name__}")
        if not isinstance(kind, str) or kind not in KINDS:
            raise ValueError(f"kind: must be one of {list(KINDS)}, got {shown(kind)}")
        pos = finite_vec(position, "position")
        ang = finite_num(angle, "angle")
        vel = finite_vec(velocity, "velocity")
        avel = finite_num(angular_velocity, "angular_velocity")
        dens = checked_density(density, shape)  # before the slot is taken: a refused add leaves nothing
        rest = finite_num(restitution, "restitution", lo=0.0, hi=1.0)
        mu_s, mu_d = friction_pair(friction)
        if name is not None:
            self._body_names.check_new(name)
        oid, s = self._bodies.add()
        B = self._bodies.view
        B.kind[s] = KINDS[kind]
        B.q[s] = ang
        B.e[s] = rest
        B.mu_s[s], B.mu_d[s] = mu_s, mu_d
        B.island[s] = -1
        B.awake[s] = 1
        self._set_shape(s, shape)
        self._set_mass(s, shape, dens)
        c, sn = math.cos(ang), math.sin(ang)
        com = B.com[s]
        B.x[s] = pos + (c * com[0] - sn * com[1], sn * com[0] + c * com[1])
        if B.kind[s] != STATIC:
            B.v[s] = vel
            B.w[s] = avel
        h = Body(self, oid, shape)
        self._handles[oid] = h
        self._body_names.add(oid, name)
        self._pipeline.invalidate()
        return h

    def _set_shape(self, s: int, shape: Shape) -> None:
        B = self._bodies.view
        if isinstance(shape, Circle):
            B.shape[s] = CIRCLE
            B.radius[s] = shape.radius
            B.vcount[s] = 0
            B.com[s] = shape.offset
        elif isinstance(shape, Polygon):
            c = shape.centroid
            B.shape[s] = POLYGON
            B.radius[s] = 0.0
            B.vstart[s] = self._verts.add(shape.vertices - c)
            B.vcount[s] = len(shape.vertices)
            B.com[s] = c
        else:
            raise ValueError(f"shape: unsupported shape type {type(shape).__name__}")
        B.bound_r[s] = shape.bounding_radius

    def _set_mass(self, s: int, shape: Shape, density: float) -> None:
        B = self._bodies.view
        m, _, inertia = shape.mass_properties(density)
        B.density[s] = density
        B.m[s] = m
        B.inertia[s] = inertia
        dyn = B.kind[s] == DYNAMIC
        B.inv_m[s] = 1.0 / m if dyn and m > 0 else 0.0
        B.inv_i[s] = 1.0 / inertia if dyn and inertia > 0 else 0.0

    def _replace_shape(self, body: Body, shape) -> None:
        """Body.set_shape: new geometry and mass about the same origin (validated first)."""
        if not isinstance(shape, Shape):
            raise ValueError(f"shape: expected a physics.Polygon or physics.Circle, got {type(shape).__name__}")
        s = body._s
        B = self._bodies.view
        dens = checked_density(float(B.density[s]), shape)
        origin = np.array(body.position)
        if B.shape[s] == POLYGON:
            self._verts.release(int(B.vcount[s]))
        self._touch_neighbours(s)
        self._set_shape(s, shape)
        self._set_mass(s, shape, dens)
        body._shape = shape
        q = B.q[s]
        c, sn = math.cos(q), math.sin(q)
        com = B.com[s]
        B.x[s] = origin + (c * com[0] - sn * com[1], sn * com[0] + c * com[1])
        self._touched(s)

    def remove(self, item) -> None:
        """Remove a body (and the springs attached to it) or a spring."""
        if isinstance(item, Spring):
            self._remove_spring(item)
            return
        if not isinstance(item, Body) or item.world is not self or not item.alive:
            raise ValueError(f"remove: {shown(item)} is not a live body or spring of this world")
        for sp in [sp for sp in self._spring_handles.values()
                   if sp.body_a is item or sp.body_b is item]:
            self._remove_spring(sp)
        s = item._s
        self._touch_neighbours(s)
        if self._bodies.view.shape[s] == POLYGON:
            self._verts.release(int(self._bodies.view.vcount[s]))
        removed, last = self._bodies.remove(item.id)
        S = self._springs.view
        ns = self._springs.n
        S.a[:ns][S.a[:ns] == last] = removed
        S.b[:ns][S.b[:ns] == last] = removed
        self._contacts.remap_removed_body(removed, last)
        del self._handles[item.id]
        self._body_names.drop(item.id)
        if self._verts.needs_compaction():
            self._verts.compact(self._bodies.view.vstart, self._bodies.view.vcount, self._bodies.n)
        self._pipeline.invalidate()

    def body(self, name: str) -> Body:
        """The body called ``name`` (KeyError if there is none)."""
        return self._handles[self._body_names.id_of(name)]

    @property
    def bodies(self) -> list[Body]:
        """Every body of the world, in slot order (a new list each call; removing a body changes the order of the rest)."""
        ids = self._bodies.view.id[: self._bodies.n]
        return [self._handles[int(i)] for i in ids]

    def _name_of_body(self, oid):
        return self._body_names.name_of(oid)

    def _rename_body(self, oid, name):
        self._body_names.rename(oid, name)

    # -- waking -------------------------------------------------------------
    def _touched(self, s: int) -> None:
        """An edit to body slot s: wake it and its sleeping island."""
        B = self._bodies.view
        n = self._bodies.n
        lab = B.island[s]
        if lab >= 0:
            mask = B.island[:n] == lab
            B.awake[:n][mask] = 1
            B.sleep_t[:n][mask] = 0.0
            B.island[:n][mask] = -1
        B.awake[s] = 1
        B.sleep_t[s] = 0.0
        self._pipeline.invalidate()

    def _touch_neighbours(self, s: int) -> None:
        """Wake whatever touches slot s (it is about to disappear or change)."""
        c = self._contacts
        for k in range(c.n):
            a, b = int(c.cur.a[k]), int(c.cur.b[k])
            if a == s:
                self._touched(b)
            elif b == s:
                self._touched(a)

    def wake_all(self) -> None:
        """Wake every body (and forget the sleeping islands)."""
        if not hasattr(self, "_store"):
            return
        n = self._bodies.n
        B = self._bodies.view
        B.awake[:n] = 1
        B.sleep_t[:n] = 0.0
        B.island[:n] = -1
        self._pipeline.invalidate()
