"""World's bodies: adding, reshaping and removing them, names, waking (a part of World)."""
from __future__ import annotations

import numpy as np

from .body import Body
from .spring import Spring
from .store import KINDS, STATIC
from .validate import checked_density, finite_num, finite_vec, friction_pair, shown
from .world_fixtures import shape_code, shape_list


def _awake_flag(awake, kind, vel, avel) -> bool:
    """``add_body``'s ``awake``, checked: only a dynamic body at rest can be created asleep."""
    if not isinstance(awake, (bool, np.bool_)):
        raise ValueError(f"awake: must be True or False, got {shown(awake)}")
    if not awake and kind != "dynamic":
        raise ValueError(f"awake: only a dynamic body can be created asleep (kind is {kind!r})")
    if not awake and (vel[0] != 0.0 or vel[1] != 0.0 or avel != 0.0):
        raise ValueError("awake: a body created asleep is at rest; give no velocity or "
                         "angular_velocity, or create it awake")
    return bool(awake)


class BodiesMixin:
    """The body half of :class:`~physics.World` (see world.py for the state it uses)."""

    # -- bodies -----------------------------------------------------------
    def add_body(self, shape, kind: str = "dynamic", position=(0.0, 0.0), angle: float = 0.0,
                 velocity=(0.0, 0.0), angular_velocity: float = 0.0, density: float = 1.0,
                 restitution: float = 0.0, friction=0.6, name: str | None = None, awake: bool = True) -> Body:
        """Add a body made of one shape or a list of shapes (one fixture each).

        ``density``, ``restitution`` and ``friction`` apply to every fixture this creates;
        mass, centre of mass and inertia are the sums over the fixtures (parallel axes).
        ``awake=False`` creates a dynamic body asleep, at rest, in an island of its own (Box2D's
        ``isAwake = false``): it costs nothing until something touches it or ``wake()`` is
        called, and touching bodies wake one another contact by contact.  It is ignored while
        ``world.sleeping`` is off, as a sleeping body would be woken at once.
        Every argument is validated and a ValueError names the bad field (a dynamic body of
        segments only has no area: refused)."""
        self._check_editable("add_body")
        shapes = shape_list(shape)
        if not isinstance(kind, str) or kind not in KINDS:
            raise ValueError(f"kind: must be one of {list(KINDS)}, got {shown(kind)}")
        pos = finite_vec(position, "position")
        ang = finite_num(angle, "angle")
        vel = finite_vec(velocity, "velocity")
        avel = finite_num(angular_velocity, "angular_velocity")
        # before the slot is taken: a refused add leaves nothing
        dens = [checked_density(density, sh) for sh in shapes][0]
        self._check_mass(KINDS[kind], shapes, dens)
        rest = finite_num(restitution, "restitution", lo=0.0, hi=1.0)
        mu_s, mu_d = friction_pair(friction)
        asleep = not _awake_flag(awake, kind, vel, avel) and self.sleeping
        if name is not None:
            self._body_names.check_new(name)
        oid, s = self._bodies.add()
        B = self._bodies.view
        B.kind[s] = KINDS[kind]
        B.q[s] = ang
        B.island[s] = -1
        B.awake[s] = 1
        h = Body(self, oid)
        h._fixtures = self._new_fixtures(h, shapes, dens, rest, mu_s, mu_d)
        self._place_body(h, pos)
        if B.kind[s] != STATIC:
            B.v[s] = vel
            B.w[s] = avel
        self._handles[oid] = h
        self._body_names.add(oid, name)
        if asleep:
            self._put_to_sleep([h])
        self._pipeline.invalidate()
        return h

    def _replace_shape(self, body: Body, shape) -> None:
        """Body.set_shape: one fixture of new geometry (the first fixture's id, material and
        filter) and the mass about the same origin (validated first)."""
        self._check_editable("set_shape")
        shapes = shape_list(shape)
        if len(shapes) != 1:
            raise ValueError("shape: set_shape takes one shape (add_fixture adds more)")
        first = body._fixtures[0]
        s = body._s
        dens = checked_density(first.density, shape)
        self._check_mass(int(self._bodies.view.kind[s]), [] if first.sensor else shapes, dens)
        origin = np.array(body.position)
        self._touch_neighbours(s)
        for fx in body._fixtures[1:]:
            self._drop_fixture_row(fx)
        F = self._store.fixtures.view
        f = first._f
        F.shape[f] = shape_code(shape)
        F.radius[f] = shape.radius
        first._shape = shape
        body._fixtures = [first]
        self._place_body(body, origin)
        self._touched(s)

    def remove(self, item) -> None:
        """Remove a body (its fixtures and the springs attached to it) or a spring."""
        self._check_editable("remove")
        if isinstance(item, Spring):
            self._remove_spring(item)
            return
        if not isinstance(item, Body) or item.world is not self or not item.alive:
            raise ValueError(f"remove: {shown(item)} is not a live body or spring of this world")
        for sp in [sp for sp in self._spring_handles.values()
                   if sp.body_a is item or sp.body_b is item]:
            self._remove_spring(sp)
        s = item._s
        self._events_freeze()  # the last step's events read rows and slots this removal changes
        # wake its island too: a sleeping pile has no contact rows (the broad phase skips sleeping
        # pairs), so the bodies resting on a removed sleeper would otherwise float
        self._touched(s)
        self._touch_neighbours(s)
        for fx in item._fixtures:
            self._drop_fixture_row(fx)
        removed, last = self._bodies.remove(item.id)
        self._store.fixtures.remap_removed_body(removed, last)
        S = self._springs.view
        ns = self._springs.n
        S.a[:ns][S.a[:ns] == last] = removed
        S.b[:ns][S.b[:ns] == last] = removed
        self._contacts.remap_removed_body(removed, last)
        del self._handles[item.id]
        self._body_names.drop(item.id)
        if self._verts.needs_compaction():
            F = self._store.fixtures.view
            self._verts.compact(F.vstart, F.vcount, self._store.fixtures.n)
            for h in self._handles.values():
                self._mirror(h)
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
        a, b = c.cur.a[: c.n], c.cur.b[: c.n]
        # the contacts of s found by the arrays, not a Python pass over every contact
        for k in np.flatnonzero((a == s) | (b == s)):
            self._touched(int(b[k]) if a[k] == s else int(a[k]))

    def _put_to_sleep(self, bodies) -> None:
        """Put ``bodies`` to sleep as one island, at rest (the loader: a saved sleeping island).  The
        label is a fresh one from the island counter, as the sleep update would give."""
        label = self._pipeline._islands.label
        label[0] += 1
        B = self._bodies.view
        for body in bodies:
            s = body._s
            B.awake[s] = 0
            B.island[s] = label[0]
            B.v[s] = 0.0
            B.w[s] = 0.0
        self._pipeline.invalidate()

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
