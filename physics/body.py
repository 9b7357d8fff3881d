"""Body handles: small Python objects that read and write the world's arrays.

A handle stores only the world and a stable id; every property goes through
the id -> slot map, so handles stay valid while other bodies are added and
removed.  Setters validate (finite, non-negative where physical) and wake
the body so edits in a running sandbox take effect at once.
"""
from __future__ import annotations

import math

import numpy as np

from .store import KIND_NAMES, KINDS
from .validate import checked_density, finite_num, finite_vec, friction_pair, shown


class Body:
    """Handle of one rigid body in a :class:`~physics.World`: a rigid set of fixtures (shapes).

    The material properties (``density``, ``friction``, ``restitution``) of a body with
    several fixtures read the first fixture's value; assigning one sets every fixture's.
    """

    __slots__ = ("_world", "_id", "_fixtures")

    def __init__(self, world, oid: int):
        self._world = world
        self._id = oid
        self._fixtures = []

    @property
    def shape(self):
        """The body's first shape (read-only: :meth:`set_shape` replaces the shapes and updates
        mass and geometry; :attr:`fixtures` lists them all)."""
        return self._fixtures[0].shape

    @property
    def fixtures(self) -> list:
        """The body's fixtures (physics.Fixture), in the order they were added (a new list each call)."""
        return list(self._fixtures)

    def add_fixture(self, shape, density=None, friction=None, restitution=None, category=1,
                    mask=(1 << 64) - 1, group=0, name=None, sensor=False):
        """Attach one more shape; returns its physics.Fixture.

        Material defaults to the first fixture's; ``category``/``mask`` are filter bits
        (0 .. 2^64 - 1), ``group`` a whole number (see physics.Fixture).  Mass, centre of mass
        and inertia follow; the body origin stays.  ``sensor=True`` makes a sensor: it adds no
        mass, never pushes, and reports the fixtures it overlaps (``world.sensor_events()``).
        ValueError naming the bad field."""
        return self._world._add_fixture(self, shape, density, friction, restitution, category, mask, group, name,
                                         sensor)

    def remove_fixture(self, fixture) -> None:
        """Detach ``fixture``; mass, centre of mass and inertia follow.  ValueError for a fixture
        of another body, the last fixture, or one whose removal leaves a dynamic body no area."""
        self._world._remove_fixture(self, fixture)

    def set_shape(self, shape) -> None:
        """Replace the shapes by one, keeping the body origin, angle, velocity, density and material.

        Mass, centre of mass, inertia and the collision geometry follow the new
        shape; ValueError (nothing changed) for a non-shape or a density this
        shape cannot carry."""
        self._world._replace_shape(self, shape)

    def _set_all(self, field: str, value) -> None:
        F = self._world._store.fixtures.view
        arr = getattr(F, field)
        for fx in self._fixtures:
            arr[fx._f] = value
        self._world._mirror(self)

    # -- plumbing ------------------------------------------------------
    @property
    def _s(self) -> int:
        try:
            return self._world._bodies.slot_of[self._id]
        except KeyError:
            raise ValueError(f"body {self._id} was removed from its world") from None

    @property
    def _B(self):
        return self._world._bodies.view

    def _rot(self):
        q = self._B.q[self._s]
        c, s = math.cos(q), math.sin(q)
        return np.array([[c, -s], [s, c]])

    @property
    def id(self) -> int:
        """Stable integer id of this body (never reused in its world)."""
        return self._id

    @property
    def alive(self) -> bool:
        """False once the body was removed from its world (the handle then refuses to read or write)."""
        return self._id in self._world._bodies.slot_of

    @property
    def world(self):
        """The World this body belongs to."""
        return self._world

    # -- state ---------------------------------------------------------
    @property
    def position(self) -> tuple[float, float]:
        """Body origin in world coordinates (the frame the shape's vertices are given in)."""
        s = self._s
        p = self._B.x[s] - self._rot() @ self._B.com[s]
        return (float(p[0]), float(p[1]))

    @position.setter
    def position(self, value):
        p = finite_vec(value, "position")
        s = self._s
        self._B.x[s] = p + self._rot() @ self._B.com[s]
        self._world._touched(s)

    @property
    def center_of_mass(self) -> tuple[float, float]:
        """World position (m) of the centre of mass (the origin plus the shape's centroid, turned by the angle)."""
        s = self._s
        return (float(self._B.x[s, 0]), float(self._B.x[s, 1]))

    @property
    def angle(self) -> float:
        """Orientation in radians (counter-clockwise, unbounded: turns accumulate). ValueError for a non-finite value."""
        return float(self._B.q[self._s])

    @angle.setter
    def angle(self, value):
        a = finite_num(value, "angle")
        origin = np.array(self.position)
        s = self._s
        self._B.q[s] = a
        self._B.x[s] = origin + self._rot() @ self._B.com[s]  # rotate about the origin
        self._world._touched(s)

    @property
    def velocity(self) -> tuple[float, float]:
        """Linear velocity (m/s) of the centre of mass, as (vx, vy). ValueError for a non-finite or malformed pair."""
        s = self._s
        return (float(self._B.v[s, 0]), float(self._B.v[s, 1]))

    @velocity.setter
    def velocity(self, value):
        self._B.v[self._s] = finite_vec(value, "velocity")
        self._world._touched(self._s)

    @property
    def angular_velocity(self) -> float:
        """Angular velocity in rad/s (counter-clockwise positive). ValueError for a non-finite value."""
        return float(self._B.w[self._s])

    @angular_velocity.setter
    def angular_velocity(self, value):
        self._B.w[self._s] = finite_num(value, "angular_velocity")
        self._world._touched(self._s)

    # -- properties ----------------------------------------------------
    @property
    def mass(self) -> float:
        """Mass in kg (density x area; 0 for static and kinematic bodies, which do not respond to forces)."""
        return float(self._B.m[self._s])

    @property
    def inertia(self) -> float:
        """Moment of inertia about the centre of mass (kg m^2)."""
        return float(self._B.inertia[self._s])

    @property
    def density(self) -> float:
        """Density in kg/m^2 (> 0); setting it recomputes mass and inertia. ValueError for zero, negative, non-finite or mass-overflowing values."""
        return float(self._B.density[self._s])

    @density.setter
    def density(self, value):
        d = [checked_density(value, fx.shape) for fx in self._fixtures][0]
        self._set_all("density", d)
        self._world._place_body(self)
        self._world._touched(self._s)

    @property
    def kind(self) -> str:
        """"dynamic", "static" or "kinematic"; setting it recomputes the mass (a static body stops). ValueError for another value."""
        return KIND_NAMES[int(self._B.kind[self._s])]

    @kind.setter
    def kind(self, value):
        if not isinstance(value, str) or value not in KINDS:
            raise ValueError(f"kind: must be one of {list(KINDS)}, got {shown(value)}")
        s = self._s
        self._world._check_mass(KINDS[value], [fx.shape for fx in self._fixtures if not fx.sensor], None)
        self._B.kind[s] = KINDS[value]
        self._world._place_body(self)
        if value == "static":  # a static body never moves
            self._B.v[s] = 0.0
            self._B.w[s] = 0.0
        self._world._touched(s)

    @property
    def restitution(self) -> float:
        """Coefficient of restitution in [0, 1]: 0 no bounce, 1 elastic. A contact uses the larger of its two bodies'. ValueError outside [0, 1] or non-finite."""
        return float(self._B.e[self._s])

    @restitution.setter
    def restitution(self, value):
        self._set_all("e", finite_num(value, "restitution", lo=0.0, hi=1.0))

    @property
    def friction(self) -> tuple[float, float]:
        """(static, dynamic) Coulomb coefficients; assign one number or a pair."""
        s = self._s
        return (float(self._B.mu_s[s]), float(self._B.mu_d[s]))

    @friction.setter
    def friction(self, value):
        mu_s, mu_d = friction_pair(value)
        self._set_all("mu_s", mu_s)
        self._set_all("mu_d", mu_d)
        self._world._touched(self._s)

    @property
    def static_friction(self) -> float:
        """Coulomb friction coefficient while sticking (>= 0); a contact combines the two bodies' by the geometric mean. ValueError for negative or non-finite values."""
        return float(self._B.mu_s[self._s])

    @static_friction.setter
    def static_friction(self, value):
        self._set_all("mu_s", finite_num(value, "static_friction", lo=0.0))

    @property
    def dynamic_friction(self) -> float:
        """Coulomb friction coefficient while sliding (>= 0); a contact combines the two bodies' by the geometric mean. ValueError for negative or non-finite values."""
        return float(self._B.mu_d[self._s])

    @dynamic_friction.setter
    def dynamic_friction(self, value):
        self._set_all("mu_d", finite_num(value, "dynamic_friction", lo=0.0))

    @property
    def name(self):
        """Optional unique name (str or None); world.body(name) finds it. ValueError when another body has it."""
        return self._world._name_of_body(self._id)

    @name.setter
    def name(self, value):
        self._world._rename_body(self._id, value)

    @property
    def awake(self) -> bool:
        """False while the body sleeps (it and its island are at rest and not simulated)."""
        return bool(self._B.awake[self._s])

    def wake(self) -> None:
        """Wake this body and its island (sleeping bodies are not simulated until woken or touched)."""
        self._world._touched(self._s)

    # -- geometry and forces -------------------------------------------
    def local_to_world(self, point) -> tuple[float, float]:
        """The world position (m) of ``point`` given in this body's coordinates. ValueError for a malformed point."""
        p = np.array(self.position) + self._rot() @ finite_vec(point, "point")
        return (float(p[0]), float(p[1]))

    def world_to_local(self, point) -> tuple[float, float]:
        """The body-coordinate position of world ``point`` (m). ValueError for a malformed point."""
        p = self._rot().T @ (finite_vec(point, "point") - np.array(self.position))
        return (float(p[0]), float(p[1]))

    def velocity_at(self, point) -> tuple[float, float]:
        """Velocity (m/s) of the body's material at world ``point``: v + w x r. ValueError for a malformed point."""
        s = self._s
        r = finite_vec(point, "point") - self._B.x[s]
        w = self._B.w[s]
        return (float(self._B.v[s, 0] - w * r[1]), float(self._B.v[s, 1] + w * r[0]))

    def apply_force(self, force, point=None) -> None:
        """Add a force (N) for the next step, at a world point (default: centre of mass)."""
        s = self._s
        f = finite_vec(force, "force")
        total = self._B.f[s] + f
        tau = self._B.tau[s]
        if point is not None:
            r = finite_vec(point, "point") - self._B.x[s]
            tau = tau + (r[0] * f[1] - r[1] * f[0])
        if not (np.all(np.isfinite(total)) and math.isfinite(tau)):
            raise ValueError(f"force: the forces accumulated on this body for the next step would overflow "
                             f"(adding {force!r} to {tuple(self._B.f[s])})")
        self._B.f[s] = total
        self._B.tau[s] = tau
        self._world._touched(s)

    def apply_impulse(self, impulse, point=None) -> None:
        """Change momentum at once by ``impulse`` (N s) at a world point."""
        s = self._s
        j = finite_vec(impulse, "impulse")
        B = self._B
        v = B.v[s] + B.inv_m[s] * j
        w = B.w[s]
        if point is not None:
            r = finite_vec(point, "point") - B.x[s]
            w = w + B.inv_i[s] * (r[0] * j[1] - r[1] * j[0])
        if not (np.all(np.isfinite(v)) and math.isfinite(w)):
            raise ValueError(f"impulse: {impulse!r} would make this body's velocity overflow")
        B.v[s] = v
        B.w[s] = w
        self._world._touched(s)

    def apply_torque(self, torque) -> None:
        """Add a torque (N m, counter-clockwise positive) for the next step; wakes the body.
        ValueError for a non-finite torque or an accumulated torque that would overflow."""
        t = self._B.tau[self._s] + finite_num(torque, "torque")
        if not math.isfinite(t):
            raise ValueError(f"torque: the torque accumulated on this body for the next step would overflow")
        self._B.tau[self._s] = t
        self._world._touched(self._s)

    def apply_angular_impulse(self, impulse) -> None:
        """Change the angular momentum at once by ``impulse`` (N m s); wakes the body.
        ValueError for a non-finite impulse or an angular velocity that would overflow."""
        s = self._s
        w = self._B.w[s] + self._B.inv_i[s] * finite_num(impulse, "impulse")
        if not math.isfinite(w):
            raise ValueError("impulse: the angular velocity would overflow")
        self._B.w[s] = w
        self._world._touched(s)

    def world_vertices(self) -> np.ndarray:
        """The first shape's polygon (or capsule/segment core) vertices in world coordinates (empty for circles)."""
        verts = getattr(self.shape, "vertices", None)
        if verts is None:
            return np.zeros((0, 2))
        return np.array(self.position) + verts @ self._rot().T

    def __repr__(self):
        if not self.alive:
            return f"<Body {self._id} (removed)>"
        nm = self.name
        return f"<Body {nm or self._id} {self.kind} at ({self.position[0]:.3g}, {self.position[1]:.3g})>"
