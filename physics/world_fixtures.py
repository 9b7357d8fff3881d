"""World's fixtures: the rows of a body's shapes, and the body's mass and frame from them (a part of World).

A body's geometry lives relative to its centre of mass, so adding, removing or re-weighing
a fixture moves the centre of mass and re-places every fixture of the body
(:meth:`_place_body`); the body origin (what users see) stays where it was.
"""
from __future__ import annotations

import math
from contextlib import contextmanager

import numpy as np

from .fixture import Fixture, filter_bits, filter_group, fixture_name
from .geometry.capsule import Capsule, Segment
from .geometry.chain import Chain, ChainSegment
from .geometry.mass import compound_mass
from .geometry.shapes import Circle, Polygon, Shape
from .store import DYNAMIC
from .store.fixtures import ALL_BITS, CAPSULE, CHAIN_SEGMENT, CIRCLE, DEFAULT_CATEGORY, POLYGON, SEGMENT
from .validate import checked_density, finite_num, flag, friction_pair

_CODES = ((Polygon, POLYGON), (Circle, CIRCLE), (Capsule, CAPSULE), (Segment, SEGMENT),
          (ChainSegment, CHAIN_SEGMENT))


def shape_code(shape) -> int:
    """The fixture table's code of a shape, or ValueError for anything else."""
    for cls, code in _CODES:
        if isinstance(shape, cls):
            return code
    raise ValueError(f"shape: expected a physics.Polygon, Circle, Capsule, Segment or Chain, "
                     f"got {type(shape).__name__}")


def shape_list(shapes, field: str = "shape") -> list:
    """One shape or a non-empty list of shapes, as a list of fixture shapes (a Chain becomes its
    segments), or ValueError naming ``field``."""
    items = [shapes] if isinstance(shapes, Shape) else shapes
    if not isinstance(items, (list, tuple)) or not items:
        raise ValueError(f"{field}: expected a shape or a non-empty list of shapes, got {type(shapes).__name__}")
    out = []
    for k, s in enumerate(items):
        if not isinstance(s, Shape):
            where = field if isinstance(shapes, Shape) else f"{field}[{k}]"
            raise ValueError(f"{where}: expected a physics shape, got {type(s).__name__}")
        if isinstance(s, Chain):
            out += s.segments
            continue
        shape_code(s)
        out.append(s)
    return out


def _extent(shape, com) -> float:
    """Distance from ``com`` (body coordinates) to the farthest point of ``shape``."""
    if isinstance(shape, Circle):
        return float(math.hypot(*(shape.offset - com))) + shape.radius
    d = shape.vertices - com
    return float(np.max(np.hypot(d[:, 0], d[:, 1]))) + shape.radius


def _extents(fx, com) -> float:
    """The largest ``_extent`` of the fixtures ``fx``, vertices taken together (one numpy pass; the
    same number, as adding a shape's radius after the max is the max of the sums)."""
    circles = [_extent(f.shape, com) for f in fx if isinstance(f.shape, Circle)]
    polys = [f.shape for f in fx if not isinstance(f.shape, Circle)]
    if polys:
        d = np.concatenate([p.vertices for p in polys]) - com
        r = np.repeat([p.radius for p in polys], [len(p.vertices) for p in polys])
        circles.append(float(np.max(np.hypot(d[:, 0], d[:, 1]) + r)))
    return max(circles)


class FixturesMixin:
    """The fixture half of :class:`~physics.World` (see world.py for the state it uses)."""

    def _check_mass(self, kind_code: int, shapes, densities) -> None:
        """A dynamic body needs area: ValueError for one made only of segments (``shapes``: the
        body's non-sensor shapes; sensors weigh nothing)."""
        if kind_code == DYNAMIC and not shapes:
            raise ValueError("sensor: a dynamic body needs a shape that is not a sensor (sensors have no mass); "
                             "make the body static or kinematic, or add a solid shape")
        if kind_code == DYNAMIC and all(s.area == 0.0 for s in shapes):
            raise ValueError("shape: a dynamic body needs a shape with area (segments and chains have none); "
                             "make it static or kinematic, or add a polygon, circle or capsule")

    def _new_fixture(self, body, shape, density, e, mu_s, mu_d, category=DEFAULT_CATEGORY, mask=ALL_BITS,
                     group=0, name=None, sensor=False) -> Fixture:
        """A fixture row for ``body`` (placed by the next :meth:`_place_body`)."""
        fid, f = self._store.fixtures.add()
        F = self._store.fixtures.view
        F.body[f] = body._s
        F.shape[f] = shape_code(shape)
        F.radius[f] = shape.radius
        F.density[f] = density
        F.e[f] = e
        F.mu_s[f], F.mu_d[f] = mu_s, mu_d
        F.category[f] = category
        F.mask[f] = mask
        F.group[f] = group
        F.sensor[f] = sensor
        self._n_sensors += bool(sensor)
        h = Fixture(self, fid, shape, body, name)
        self._fixture_handles[fid] = h
        return h

    def _new_fixtures(self, body, shapes, density, e, mu_s, mu_d) -> list:
        """Fixture rows of one material for ``shapes`` at once (what ``_new_fixture`` makes for
        each, with the default filter and no name: add_body's 100,000 chain segments)."""
        if len(shapes) == 1:  # most bodies: the row element by element, no lists or slices
            return [self._new_fixture(body, shapes[0], density, e, mu_s, mu_d)]
        ids, rows = self._store.fixtures.add_many(len(shapes))
        F = self._store.fixtures.view
        r = slice(rows.start, rows.stop)
        F.body[r] = body._s
        F.shape[r] = [shape_code(sh) for sh in shapes]
        F.radius[r] = [sh.radius for sh in shapes]
        F.density[r], F.e[r], F.mu_s[r], F.mu_d[r] = density, e, mu_s, mu_d
        F.category[r], F.mask[r] = DEFAULT_CATEGORY, ALL_BITS
        out = [Fixture(self, fid, sh, body) for fid, sh in zip(ids, shapes)]
        self._fixture_handles.update(zip(ids, out))
        return out

    def _drop_fixture_row(self, fx: Fixture) -> None:
        F = self._store.fixtures.view
        f = fx._f
        self._events_freeze()  # the last step's events read rows this removal renumbers
        self._n_sensors -= int(F.sensor[f] != 0)
        if F.vcount[f]:
            self._verts.release(int(F.vcount[f]))
        self._store.fixtures.remove(fx.id)
        del self._fixture_handles[fx.id]
        self._gone_fixtures[fx.id] = fx  # the next step's end events still name it

    @contextmanager
    def _placing_once(self):
        """``with world._placing_once():`` fixture edits inside place each body they touch once,
        on exit, instead of once per edit: re-placing is linear in the body's fixtures, so a body
        built fixture by fixture would cost their square (a ground of 2,500 boxes: minutes)."""
        if getattr(self, "_pending_place", None) is not None:  # nested: the outer one places
            yield
            return
        self._pending_place = {}
        try:
            yield
        finally:
            pending, self._pending_place = self._pending_place, None
            for body, origin in pending.values():
                if body.alive:
                    self._place_body(body, origin)

    def _place_body(self, body, origin=None) -> None:
        """Mass, centre of mass, inertia and fixture geometry of ``body`` from its fixtures.

        The body origin (``origin``, else where it is) and angle stay; the centre of mass moves.
        Inside :meth:`_placing_once` this is deferred to its end (the origin is unchanged until
        then: position and centre of mass are still each other's).
        """
        self._check_editable("the body's fixtures")
        pending = getattr(self, "_pending_place", None)
        if pending is not None:
            prev = pending.get(id(body))
            pending[id(body)] = (body, origin if origin is not None else (prev[1] if prev else None))
            return
        s = body._s
        B = self._bodies.view
        F = self._store.fixtures.view
        old_com = B.com[s].copy()
        move = origin is not None
        if origin is None:
            origin = np.array(body.position)
        fx = body._fixtures
        slots = [f._f for f in fx]
        parts = [f.shape.mass_properties(float(F.density[k])) for f, k in zip(fx, slots)]
        solid = [p for p, k in zip(parts, slots) if not F.sensor[k]]
        # sensors weigh nothing; a body of sensors only (static or kinematic) keeps their frame
        m, com, inertia = compound_mass(solid if solid and len(solid) < len(parts) else parts)
        B.m[s] = m
        B.inertia[s] = inertia
        dyn = B.kind[s] == DYNAMIC
        B.inv_m[s] = 1.0 / m if dyn and m > 0 else 0.0
        B.inv_i[s] = 1.0 / inertia if dyn and inertia > 0 else 0.0
        B.com[s] = com
        self._place_geometry(fx, slots, com)
        # one shape: its own bounding radius (the number the recorded end states were made with)
        B.bound_r[s] = fx[0].shape.bounding_radius if len(fx) == 1 else _extents(fx, com)
        if move or not np.array_equal(old_com, com):  # an unmoved centre keeps x to the bit
            q = B.q[s]
            c, sn = math.cos(q), math.sin(q)
            B.x[s] = origin + (c * com[0] - sn * com[1], sn * com[0] + c * com[1])
        if self._verts.needs_compaction():
            n = self._store.fixtures.n
            self._verts.compact(F.vstart, F.vcount, n)
            for h in self._handles.values():
                self._mirror(h)
        self._mirror(body)

    def _place_geometry(self, fx, slots, com) -> None:
        """Fixture rows' geometry relative to the centre of mass ``com``: vertices (in place when the
        count is unchanged, new ones appended in one pass), circle centres and chain ghosts."""
        F = self._store.fixtures.view
        fresh, fresh_rows = [], []
        for f, k in zip(fx, slots):
            shape = f.shape
            if isinstance(shape, Circle):
                if F.vcount[k]:
                    self._verts.release(int(F.vcount[k]))
                    F.vcount[k] = 0
                F.center[k] = shape.offset - com
                continue
            count = len(shape.vertices)
            if F.vcount[k] and F.vcount[k] != count:
                self._verts.release(int(F.vcount[k]))
                F.vcount[k] = 0
            if F.vcount[k]:  # same count: in place (the pool's layout does not depend on edits)
                self._verts.set(int(F.vstart[k]), shape.vertices - com)
            else:
                fresh.append(shape.vertices - com)
                fresh_rows.append(k)
        if fresh:
            rows = np.array(fresh_rows)
            F.vstart[rows] = self._verts.add_many(fresh)
            F.vcount[rows] = [len(v) for v in fresh]
        ghosts = [(k, f.shape.ghost) for f, k in zip(fx, slots) if isinstance(f.shape, ChainSegment)]
        if ghosts:
            F.ghost[np.array([k for k, _ in ghosts])] = np.array([g for _, g in ghosts]) - com

    def _mirror(self, body) -> None:
        """Copy the first fixture into the body's first-fixture fields (store/bodies.py)."""
        s = body._s
        B = self._bodies.view
        F = self._store.fixtures.view
        k = body._fixtures[0]._f
        B.shape[s] = F.shape[k]
        B.radius[s] = F.radius[k]
        B.vstart[s] = F.vstart[k]
        B.vcount[s] = F.vcount[k]
        B.density[s] = F.density[k]
        B.e[s] = F.e[k]
        B.mu_s[s], B.mu_d[s] = F.mu_s[k], F.mu_d[k]

    # -- the body's API ----------------------------------------------------
    def _add_fixture(self, body, shape, density=None, friction=None, restitution=None, category=DEFAULT_CATEGORY,
                     mask=ALL_BITS, group=0, name=None, sensor=False) -> Fixture:
        """Body.add_fixture: validated; material defaults to the body's first fixture's."""
        self._check_editable("add_fixture")
        shapes = shape_list(shape)
        if len(shapes) != 1:
            raise ValueError("shape: add_fixture takes one shape (a chain: add it to the body with add_body)")
        first = body._fixtures[0]
        dens = checked_density(first.density if density is None else density, shape)
        mu_s, mu_d = friction_pair(first.friction if friction is None else friction)
        e = finite_num(first.restitution if restitution is None else restitution, "restitution", lo=0.0, hi=1.0)
        cat, msk = filter_bits(category, "category"), filter_bits(mask, "mask")
        grp, nm = filter_group(group), fixture_name(name)
        sens = flag(sensor, "sensor")
        self._touch_neighbours(body._s)
        fx = self._new_fixture(body, shape, dens, e, mu_s, mu_d, cat, msk, grp, nm, sens)
        body._fixtures.append(fx)
        self._place_body(body)
        self._touched(body._s)
        return fx

    def _remove_fixture(self, body, fx) -> None:
        """Body.remove_fixture: ValueError for a fixture of another body or the body's last one."""
        self._check_editable("remove_fixture")
        if not isinstance(fx, Fixture) or fx.body is not body or not fx.alive:
            raise ValueError(f"remove_fixture: {fx!r} is not a live fixture of this body")
        rest = [f for f in body._fixtures if f is not fx]
        if not rest:
            raise ValueError("remove_fixture: a body keeps at least one fixture (remove the body instead)")
        self._check_mass(int(self._bodies.view.kind[body._s]), [f.shape for f in rest if not f.sensor], None)
        self._touch_neighbours(body._s)
        origin = np.array(body.position)
        self._drop_fixture_row(fx)
        body._fixtures = rest
        self._place_body(body, origin)
        self._touched(body._s)

    def _set_sensor(self, fx, value) -> None:
        """Fixture.sensor's setter: the body's mass follows; its contacts end or begin next step."""
        self._check_editable("sensor")
        on = flag(value, "sensor")
        F = self._store.fixtures.view
        f = fx._f
        if bool(F.sensor[f]) == on:
            return
        body = fx.body
        solid = [g.shape for g in body._fixtures if g is not fx and not g.sensor] + ([] if on else [fx.shape])
        self._check_mass(int(self._bodies.view.kind[body._s]), solid, None)
        self._touch_neighbours(body._s)
        F.sensor[f] = on
        self._n_sensors += 1 if on else -1
        self._place_body(body)
        self._touched(body._s)
