"""The public face of the core: World, with body and spring handles.

State lives in arrays (physics/store.py); this module validates input,
keeps names and handles, and hands each step to the pipeline.
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np

from . import options, solvers
from .body import Body, checked_density, finite_num, finite_vec, friction_pair
from .contacts import ContactBuffer
from .errors import SimulationError
from .pipeline import Pipeline
from .shapes import Circle, Polygon, Shape
from .spring import Spring
from .store import (BODY_FIELDS, CIRCLE, DYNAMIC, KINDS, POLYGON, SPRING_FIELDS, STATIC, Bodies, Springs,
                    Table, VertexPool)


STATE_DTYPE = np.dtype([("id", np.int64), ("position", np.float64, (2,)), ("angle", np.float64),
                        ("velocity", np.float64, (2,)), ("angular_velocity", np.float64), ("awake", np.bool_)])

Contact = namedtuple("Contact", "body_a body_b points normal depth")
RenderData = namedtuple(
    "RenderData",
    "vertices vstart vcount kind awake shape radius center angle com ids aabb "
    "spring_ends contact_points contact_normals")


class World:
    """A 2D rigid-body world.

    ``World(gravity=(0, -9.81), dt=1/60, solver="soft_step")``; add bodies with
    :meth:`add_body`, springs with :meth:`add_spring`, advance with :meth:`step`.
    Contacts combine friction by the geometric mean and restitution by the
    maximum of the two bodies' coefficients.
    """

    def __init__(self, gravity=(0.0, -9.81), dt: float = 1 / 60, solver: str = "soft_step",
                 integrator: str = "symplectic_euler", sleeping: bool = True,
                 broadphase: str = "auto", narrowphase: str = "sat", settings: dict | None = None):
        self._bodies = Table(BODY_FIELDS, Bodies, cap=64)
        self._springs = Table(SPRING_FIELDS, Springs, cap=16)
        self._verts = VertexPool()
        self._contacts = ContactBuffer()
        self._handles: dict[int, Body] = {}
        self._spring_handles: dict[int, Spring] = {}
        self._body_names: dict[str, int] = {}
        self._body_name_of: dict[int, str] = {}
        self._spring_names: dict[str, int] = {}
        self._spring_name_of: dict[int, str] = {}
        self._mode_settings: dict[str, dict] = {}
        self._pipeline = Pipeline()
        #: what the scene file this world came from says of itself (name, description, camera);
        #: saving writes it back.  Edit it to change what is saved.
        self.metadata: dict = {}
        self.time = 0.0
        self.steps = 0
        self.fault: SimulationError | None = None
        # collision tolerances (metres): contacts within `linear_slop` count as resting, and
        # the speculative margin catches pairs that will touch during the step
        self.linear_slop = 0.005
        self.speculative_distance = 4 * self.linear_slop
        # sleeping thresholds (Box2D v3-like): an island sleeps once every body's centre and rim
        # (angular speed x bounding radius) stay below `sleep_linear` for `time_to_sleep` seconds;
        # `sleep_angular` caps the spin of tiny bodies, whose rims are slow even when spinning
        self.sleep_linear = 0.05
        self.sleep_angular = 0.5
        self.time_to_sleep = 0.5
        self.gravity = gravity
        self.dt = dt
        self.integrator = integrator
        self.broadphase = broadphase
        self.narrowphase = narrowphase
        self.solver = solver
        self.sleeping = sleeping
        for k, v in (settings or {}).items():
            self.settings[k] = v

    # -- settings -------------------------------------------------------
    @property
    def gravity(self) -> tuple[float, float]:
        return (float(self._gravity[0]), float(self._gravity[1]))

    @gravity.setter
    def gravity(self, value):
        self._gravity = finite_vec(value, "gravity")
        self.wake_all()

    @property
    def dt(self) -> float:
        return self._dt

    @dt.setter
    def dt(self, value):
        self._dt = finite_num(value, "dt", lo=0.0, lo_open=True)

    @property
    def solver(self) -> str:
        return self._solver_name

    @solver.setter
    def solver(self, name):
        mode = solvers.get(name)  # ValueError for an unknown name, ImportError for a broken module
        self._solver_name = name
        self._mode = mode
        self._mode_settings.setdefault(name, {k: s.default for k, s in mode.settings.items()})
        self._pipeline.invalidate()

    @property
    def solvers(self) -> list[str]:
        """Every solver mode the core has."""
        return solvers.available()

    @property
    def settings(self) -> "ModeSettings":
        """The current solver's parameters: ``world.settings["substeps"] = 8``."""
        return ModeSettings(self, self._solver_name)

    def settings_for(self, solver: str) -> "ModeSettings":
        self._mode_settings.setdefault(solver, {k: s.default for k, s in solvers.get(solver).settings.items()})
        return ModeSettings(self, solver)

    @property
    def integrator(self) -> str:
        return self._integrator

    @integrator.setter
    def integrator(self, name):
        options.code(options.INTEGRATORS, name, "integrator")
        self._integrator = name

    @property
    def broadphase(self) -> str:
        return self._broadphase

    @broadphase.setter
    def broadphase(self, name):
        options.code(options.BROADPHASES, name, "broad phase")
        self._broadphase = name

    @property
    def narrowphase(self) -> str:
        return self._narrowphase

    @narrowphase.setter
    def narrowphase(self, name):
        options.code(options.NARROWPHASES, name, "narrow phase")
        self._narrowphase = name

    @property
    def sleeping(self) -> bool:
        return self._sleeping

    @sleeping.setter
    def sleeping(self, on):
        self._sleeping = bool(on)
        if not on:
            self.wake_all()

    # -- bodies -----------------------------------------------------------
    def add_body(self, shape: Shape, kind: str = "dynamic", position=(0.0, 0.0), angle: float = 0.0,
                 velocity=(0.0, 0.0), angular_velocity: float = 0.0, density: float = 1.0,
                 restitution: float = 0.0, friction=0.6, name: str | None = None) -> Body:
        """Add a body; every argument is validated and a ValueError names the bad field."""
        if not isinstance(shape, Shape):
            raise ValueError(f"shape: expected a physics.Polygon or physics.Circle, got {type(shape).__name__}")
        if kind not in KINDS:
            raise ValueError(f"kind: must be one of {list(KINDS)}, got {kind!r}")
        pos = finite_vec(position, "position")
        ang = finite_num(angle, "angle")
        vel = finite_vec(velocity, "velocity")
        avel = finite_num(angular_velocity, "angular_velocity")
        dens = checked_density(density, shape)  # before the slot is taken: a refused add leaves nothing
        rest = finite_num(restitution, "restitution", lo=0.0, hi=1.0)
        mu_s, mu_d = friction_pair(friction)
        if name is not None:
            self._check_new_name(name, self._body_names, "body")
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
        if name is not None:
            self._body_names[name] = oid
            self._body_name_of[oid] = name
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
            start = self._verts.add(shape.vertices - c)
            B = self._bodies.view  # (the pool does not touch bodies; kept for clarity)
            B.vstart[s] = start
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

    def remove(self, item) -> None:
        """Remove a body (and the springs attached to it) or a spring."""
        if isinstance(item, Spring):
            self._remove_spring(item)
            return
        if not isinstance(item, Body) or item.world is not self or not item.alive:
            raise ValueError(f"remove: {item!r} is not a live body or spring of this world")
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
        nm = self._body_name_of.pop(item.id, None)
        if nm is not None:
            del self._body_names[nm]
        if self._verts.needs_compaction():
            self._verts.compact(self._bodies.view.vstart, self._bodies.view.vcount, self._bodies.n)
        self._pipeline.invalidate()

    def body(self, name: str) -> Body:
        try:
            return self._handles[self._body_names[name]]
        except KeyError:
            raise KeyError(f"no body named {name!r}") from None

    @property
    def bodies(self) -> list[Body]:
        ids = self._bodies.view.id[: self._bodies.n]
        return [self._handles[int(i)] for i in ids]

    def _name_of_body(self, oid):
        return self._body_name_of.get(oid)

    def _rename_body(self, oid, name):
        self._rename(oid, name, self._body_names, self._body_name_of, "body")

    # -- springs ----------------------------------------------------------
    def add_spring(self, body_a: Body, body_b: Body | None = None, anchor_a=(0.0, 0.0), anchor_b=(0.0, 0.0),
                   stiffness: float = 100.0, damping: float = 0.0, rest_length: float | None = None,
                   name: str | None = None) -> Spring:
        """A damped spring from ``anchor_a`` on ``body_a`` (body coordinates) to ``anchor_b`` on
        ``body_b``, or to the world point ``anchor_b`` when ``body_b`` is None.  The rest length
        defaults to the current distance between the anchors."""
        for b, field in ((body_a, "body_a"), (body_b, "body_b")):
            if b is None and field == "body_b":
                continue
            if not isinstance(b, Body) or b.world is not self or not b.alive:
                raise ValueError(f"{field}: expected a live body of this world, got {b!r}")
        if body_a is body_b:
            raise ValueError("body_b: a spring needs two different bodies (or None for a world anchor)")
        la = finite_vec(anchor_a, "anchor_a")
        lb = finite_vec(anchor_b, "anchor_b")
        k = finite_num(stiffness, "stiffness", lo=0.0)
        c = finite_num(damping, "damping", lo=0.0)
        if name is not None:
            self._check_new_name(name, self._spring_names, "spring")
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
        if name is not None:
            self._spring_names[name] = oid
            self._spring_name_of[oid] = name
        self._touched(body_a._s)
        if body_b is not None:
            self._touched(body_b._s)
        self._pipeline.invalidate()
        return h

    def _remove_spring(self, sp: Spring) -> None:
        if sp._world is not self or not sp.alive:
            raise ValueError(f"remove: {sp!r} is not a live spring of this world")
        if sp.body_a.alive:
            self._touched(sp.body_a._s)
        if sp.body_b is not None and sp.body_b.alive:
            self._touched(sp.body_b._s)
        self._springs.remove(sp.id)
        del self._spring_handles[sp.id]
        nm = self._spring_name_of.pop(sp.id, None)
        if nm is not None:
            del self._spring_names[nm]
        self._pipeline.invalidate()

    def spring(self, name: str) -> Spring:
        try:
            return self._spring_handles[self._spring_names[name]]
        except KeyError:
            raise KeyError(f"no spring named {name!r}") from None

    @property
    def springs(self) -> list[Spring]:
        ids = self._springs.view.id[: self._springs.n]
        return [self._spring_handles[int(i)] for i in ids]

    def _name_of_spring(self, oid):
        return self._spring_name_of.get(oid)

    def _rename_spring(self, oid, name):
        self._rename(oid, name, self._spring_names, self._spring_name_of, "spring")

    # -- names ------------------------------------------------------------
    @staticmethod
    def _check_new_name(name, table, what):
        if not isinstance(name, str) or not name:
            raise ValueError(f"name: a {what} name must be a non-empty string, got {name!r}")
        if name in table:
            raise ValueError(f"name: a {what} named {name!r} already exists")

    def _rename(self, oid, name, names, name_of, what):
        old = name_of.get(oid)
        if name == old:
            return
        if name is not None:
            self._check_new_name(name, names, what)
        if old is not None:
            del names[old]
            del name_of[oid]
        if name is not None:
            names[name] = oid
            name_of[oid] = name

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
        if not hasattr(self, "_bodies"):
            return
        n = self._bodies.n
        B = self._bodies.view
        B.awake[:n] = 1
        B.sleep_t[:n] = 0.0
        B.island[:n] = -1
        self._pipeline.invalidate()

    # -- stepping -----------------------------------------------------------
    def step(self, dt: float | None = None) -> None:
        """Advance the world by ``dt`` (default ``world.dt``).

        Raises :class:`SimulationError` (and leaves the world as it was before the
        step) if the step would produce a non-finite value.
        """
        h = self._dt if dt is None else finite_num(dt, "dt", lo=0.0, lo_open=True)
        self._pipeline.step(self, h)

    def info(self) -> dict:
        """Counts, solver and the pipeline stages this world runs."""
        return self._pipeline.info(self)

    # -- queries ------------------------------------------------------------
    def contacts(self) -> list[Contact]:
        """Touching contacts of the last step (normal from body_a to body_b, depth > -slop)."""
        c = self._contacts
        out = []
        ids = self._bodies.view.id
        for k in range(c.n):
            m = int(c.cur.count[k])
            keep = [p for p in range(m) if c.cur.depth[k, p] > -self.linear_slop]
            if not keep:
                continue
            out.append(Contact(self._handles[int(ids[c.cur.a[k]])], self._handles[int(ids[c.cur.b[k]])],
                               [tuple(map(float, c.cur.point[k, p])) for p in keep],
                               tuple(map(float, c.cur.normal[k])),
                               max(float(c.cur.depth[k, p]) for p in keep)))
        return out

    def query_point(self, point) -> Body | None:
        """The topmost (last added) body containing a world point, or None."""
        p = finite_vec(point, "point")
        n = self._bodies.n
        B = self._bodies.view
        self._pipeline.refresh_geometry(self)
        box = B.aabb[:n]
        cand = np.nonzero((box[:, 0] <= p[0]) & (p[0] <= box[:, 2]) & (box[:, 1] <= p[1]) & (p[1] <= box[:, 3]))[0]
        V = self._verts.view
        for s in cand[::-1]:
            if B.shape[s] == CIRCLE:
                if np.hypot(*(p - B.x[s])) <= B.radius[s]:
                    return self._handles[int(B.id[s])]
                continue
            a, k = int(B.vstart[s]), int(B.vcount[s])
            if np.all(np.einsum("ij,ij->i", p - V.world[a:a + k], V.wnormal[a:a + k]) <= 0):
                return self._handles[int(B.id[s])]
        return None

    def state(self) -> np.ndarray:
        """Every body's state as a read-only numpy structured array (a copy), in body order.

        Fields: ``id`` (int64), ``position`` (2: the body origin, m), ``angle`` (rad),
        ``velocity`` (2: of the centre of mass, m/s), ``angular_velocity`` (rad/s), ``awake``
        (bool).  ``world.state()["position"]`` equals ``[b.position for b in world.bodies]``.
        """
        n = self._bodies.n
        B = self._bodies.view
        out = np.zeros(n, STATE_DTYPE)
        q = B.q[:n]
        c, s = np.cos(q), np.sin(q)
        com = B.com[:n]
        out["id"] = B.id[:n]
        out["position"][:, 0] = B.x[:n, 0] - (c * com[:, 0] - s * com[:, 1])
        out["position"][:, 1] = B.x[:n, 1] - (s * com[:, 0] + c * com[:, 1])
        out["angle"] = q
        out["velocity"] = B.v[:n]
        out["angular_velocity"] = B.w[:n]
        out["awake"] = B.awake[:n] != 0
        out.setflags(write=False)
        return out

    def kinetic_energy(self) -> float:
        n = self._bodies.n
        B = self._bodies.view
        dyn = B.kind[:n] == DYNAMIC
        v2 = (B.v[:n] ** 2).sum(1)
        return float(0.5 * (B.m[:n] * v2 + B.inertia[:n] * B.w[:n] ** 2)[dyn].sum())

    def potential_energy(self) -> float:
        """Gravitational (relative to the origin) plus elastic energy of the springs."""
        n = self._bodies.n
        B = self._bodies.view
        dyn = B.kind[:n] == DYNAMIC
        pe = float(-(B.m[:n, None] * B.x[:n] @ self._gravity)[dyn].sum())
        for sp in self.springs:
            pe += 0.5 * sp.stiffness * (sp.length - sp.rest_length) ** 2
        return pe

    def linear_momentum(self) -> tuple[float, float]:
        n = self._bodies.n
        B = self._bodies.view
        dyn = B.kind[:n] == DYNAMIC
        p = (B.m[:n, None] * B.v[:n])[dyn].sum(0)
        return (float(p[0]), float(p[1]))

    def angular_momentum(self, about=(0.0, 0.0)) -> float:
        n = self._bodies.n
        B = self._bodies.view
        dyn = B.kind[:n] == DYNAMIC
        r = B.x[:n] - finite_vec(about, "about")
        L = B.m[:n] * (r[:, 0] * B.v[:n, 1] - r[:, 1] * B.v[:n, 0]) + B.inertia[:n] * B.w[:n]
        return float(L[dyn].sum())

    def render_data(self) -> RenderData:
        """Arrays for drawing (views into the world's state: read, do not write)."""
        self._pipeline.refresh_geometry(self)
        n = self._bodies.n
        B = self._bodies.view
        V = self._verts.view
        S = self._springs.view
        ns = self._springs.n
        ends = np.zeros((ns, 2, 2))
        if ns:
            ends[:, 0] = _anchor_world(B, S.a[:ns], S.la[:ns])
            world_b = S.b[:ns] < 0
            ends[:, 1] = np.where(world_b[:, None], S.lb[:ns],
                                  _anchor_world(B, np.maximum(S.b[:ns], 0), S.lb[:ns]))
        c = self._contacts
        cnt = c.cur.count[: c.n].astype(np.int64)
        mask = np.arange(2)[None, :] < cnt[:, None]
        pts = c.cur.point[: c.n][mask]
        nrm = np.repeat(c.cur.normal[: c.n], cnt, axis=0)
        return RenderData(V.world[: self._verts.top], B.vstart[:n], B.vcount[:n], B.kind[:n], B.awake[:n],
                          B.shape[:n], B.radius[:n], B.x[:n], B.q[:n], B.com[:n], B.id[:n], B.aabb[:n],
                          ends, pts, nrm)

    def quadtree_cells(self) -> np.ndarray:
        """Rectangles (K, 4: min x, min y, max x, max y) of the broad phase's quadtree over the
        current AABBs, for debug overlays (built on demand; stepping does not need it)."""
        from .broadphase import quadtree_cells
        self._pipeline.refresh_geometry(self)
        return quadtree_cells(self._bodies.view, self._bodies.n)

    def save_scene(self, path, name: str | None = None, description: str | None = None) -> None:
        """Write this world as a scene file (atomically: temp file + rename)."""
        from .scene.save import save_scene  # lazy, and save imports nothing that imports world
        save_scene(self, path, name=name, description=description)

    def __repr__(self):
        return (f"<World {self._bodies.n} bodies, {self._springs.n} springs, solver={self._solver_name}, "
                f"t={self.time:.3f}>")


def _anchor_world(B, slots, local):
    q = B.q[slots]
    c, s = np.cos(q), np.sin(q)
    return B.x[slots] + np.stack([c * local[:, 0] - s * local[:, 1], s * local[:, 0] + c * local[:, 1]], 1)


class ModeSettings:
    """Dict-like view of one solver mode's parameters, validated on assignment."""

    def __init__(self, world: World, solver: str):
        self._world = world
        self._solver = solver
        self._decl = solvers.get(solver).settings
        self._values = world._mode_settings[solver]

    def __getitem__(self, key):
        if key not in self._decl:
            raise KeyError(f"solver '{self._solver}' has no setting {key!r}; it has {list(self._decl)}")
        return self._values[key]

    def __setitem__(self, key, value):
        if key not in self._decl:
            raise KeyError(f"solver '{self._solver}' has no setting {key!r}; it has {list(self._decl)}")
        self._values[key] = self._decl[key].coerce(value)

    def __iter__(self):
        return iter(self._decl)

    def __len__(self):
        return len(self._decl)

    def __contains__(self, key):
        return key in self._decl

    def items(self):
        return [(k, self._values[k]) for k in self._decl]

    def keys(self):
        return list(self._decl)

    def declared(self):
        return dict(self._decl)

    def update(self, other=(), **kw):
        for k, v in dict(other, **kw).items():
            self[k] = v

    def to_dict(self) -> dict:
        return dict(self.items())

    def __repr__(self):
        return f"ModeSettings({self._solver}, {self.to_dict()})"
