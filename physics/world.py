"""The public face of the core: World, with body and spring handles.

State lives in arrays (physics/store/); this module validates input, keeps
names and handles, and hands each step to the pipeline (physics/step/).
"""
from __future__ import annotations

import math
import warnings

import numpy as np

from . import measures, options, solvers, threads, views
from .body import Body
from .errors import SimulationError
from .metadata import Metadata
from .names import Names
from .settings import ModeSettings, ModeValues
from .spring import Spring
from .step.pipeline import Pipeline
from .store import Store
from .collision.broadphase.limit import MAX_PAIRS
from .validate import finite_num, finite_vec, flag, whole
from .views import STATE_DTYPE, Contact, RenderData
from .world_bodies import BodiesMixin
from .world_fixtures import FixturesMixin
from .world_joints import JointsMixin
from .world_queries import QueriesMixin
from .world_batch import BatchMixin
from .world_springs import SpringsMixin
from .world_snapshot import SnapshotMixin
from .world_events import EventsMixin

__all__ = ["World", "Contact", "RenderData", "STATE_DTYPE", "DT_MIN", "DT_MAX"]

#: the shortest step (s): below it 1/dt and the sub-step rates leave the float range
DT_MIN = 1e-9
#: the longest step (s): one hour.  Far beyond any stable rigid-body step, and world.time (dt
#: summed) stays finite for any count of steps a run can make (World(dt=1e308) stepped it to inf)
DT_MAX = 3600.0


def _tolerance(field: str, doc: str = ""):
    """A validated non-negative world setting that the step context reads (refreshed on change)."""
    private = "_" + field

    def get(self) -> float:
        return getattr(self, private)

    def put(self, value) -> None:
        setattr(self, private, finite_num(value, field, lo=0.0))
        self._pipeline.dirty = True
        for vals in self._settings.values():  # the settings a scene calls for are in slops
            vals.fitted_at = None
    return property(get, put, doc=doc)


class World(JointsMixin, QueriesMixin, BatchMixin, BodiesMixin, FixturesMixin, SpringsMixin, SnapshotMixin,
            EventsMixin):
    """A 2D rigid-body world.

    ``World(gravity=(0, -9.81), dt=1/60, solver="soft_step")``; add bodies with
    :meth:`~physics.World.add_body`, springs with :meth:`~physics.World.add_spring`, joints with
    :meth:`~physics.World.add_joint`, advance with :meth:`step`.
    Contacts combine friction by the geometric mean and restitution by the
    maximum of the two bodies' coefficients.

    >>> import physics
    >>> w = physics.World(gravity=(0, -10))
    >>> ground = w.add_body(physics.Polygon.box(10, 1), kind="static", position=(0, -0.5))
    >>> ball = w.add_body(physics.Circle(0.5), position=(0, 5), name="ball")
    >>> for _ in range(180):   # 3 s at the default 60 steps per second
    ...     w.step()
    >>> round(ball.position[1], 1)   # it fell 4.5 m and rests on the ground
    0.5
    >>> w.body("ball") is ball, round(w.time, 6)
    (True, 3.0)
    """

    def __init__(self, gravity=(0.0, -9.81), dt: float = 1 / 60, solver: str = options.DEFAULT_SOLVER,
                 integrator: str = options.DEFAULT_INTEGRATOR, sleeping: bool = True,
                 broadphase: str = options.DEFAULT_BROADPHASE, narrowphase: str = options.DEFAULT_NARROWPHASE,
                 settings: dict | None = None):
        self._store = Store()
        self._handles: dict[int, Body] = {}
        self._fixture_handles = {}
        self._spring_handles: dict[int, Spring] = {}
        self._body_names = Names("body")
        self._spring_names = Names("spring")
        self._joint_handles = {}
        self._joint_names = Names("joint")
        self._settings: dict[str, ModeValues] = {}
        self._pipeline = Pipeline()
        self._n_sensors = 0  # sensor fixtures: the step splits sensor pairs off only when there are any
        self._gone_fixtures = {}  # removed fixtures the next step's end events still name
        self._pair_filter = None
        self._in_callback = 0  # > 0 while a user callback (pair_filter) runs inside step()
        self._hit_event_threshold = 1.0  # world.hit_event_threshold (world_events.py)
        #: what the scene file this world came from says of itself (name, description, camera);
        #: saving writes it back.  Edit it to change what is saved.
        self._metadata = Metadata()
        self._time = 0.0
        self.steps = 0
        """Number of step() calls completed."""
        self.fault: SimulationError | None = None
        """The last SimulationError a step raised (the world was reverted to the state before it), or None."""
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
        self.max_pairs = MAX_PAIRS
        self.energy_guard = 1.0
        self.threads = threads.available()
        self.gravity = gravity
        self.dt = dt
        self.integrator = integrator
        self.broadphase = broadphase
        self.narrowphase = narrowphase
        self.solver = solver
        self.sleeping = sleeping
        if settings:
            self.settings.update(settings)
        self._say_unused_integrator()

    # -- the store (for the sandbox, the benchmark and tests that look inside) ------------
    @property
    def _bodies(self):
        return self._store.bodies

    @property
    def _springs(self):
        return self._store.springs

    @property
    def _verts(self):
        return self._store.verts

    @property
    def _contacts(self):
        return self._store.contacts

    # -- settings -------------------------------------------------------
    linear_slop = _tolerance("linear_slop", "Contact distance (m, >= 0; default 0.005) within which touching bodies count as resting: penetration up to it is not pushed out. ValueError for negative or non-finite values.")
    """Contact distance (m, >= 0; default 0.005) within which touching bodies count as resting: penetration up to it is not pushed out. ValueError for negative or non-finite values."""
    speculative_distance = _tolerance("speculative_distance", "Margin (m, >= 0; default 4 x linear_slop) within which separated shapes already get contact rows, so a pair that closes during the step is caught. ValueError for negative or non-finite values.")
    """Margin (m, >= 0; default 4 x linear_slop) within which separated shapes already get contact rows, so a pair that closes during the step is caught. ValueError for negative or non-finite values."""
    sleep_linear = _tolerance("sleep_linear", "Speed (m/s, >= 0; default 0.05) below which a body's centre and rim count as at rest for sleeping. ValueError for negative or non-finite values.")
    """Speed (m/s, >= 0; default 0.05) below which a body's centre and rim count as at rest for sleeping. ValueError for negative or non-finite values."""
    sleep_angular = _tolerance("sleep_angular", "Angular speed (rad/s, >= 0; default 0.5) below which a small body counts as at rest for sleeping. ValueError for negative or non-finite values.")
    """Angular speed (rad/s, >= 0; default 0.5) below which a small body counts as at rest for sleeping. ValueError for negative or non-finite values."""
    time_to_sleep = _tolerance("time_to_sleep", "Seconds (>= 0; default 0.5) an island must stay at rest before it falls asleep. ValueError for negative or non-finite values.")
    """Seconds (>= 0; default 0.5) an island must stay at rest before it falls asleep. ValueError for negative or non-finite values."""

    @property
    def max_pairs(self) -> int:
        """The most candidate body pairs one step may examine (default 1,000,000: about 1 GB of
        contact rows); a step that would need more raises SimulationError at the 'broadphase'
        stage instead of exhausting memory.  A whole number >= 1 (ValueError otherwise)."""
        return self._max_pairs

    @max_pairs.setter
    def max_pairs(self, value):
        self._max_pairs = whole(value, "max_pairs", lo=1)

    @property
    def energy_guard(self) -> float:
        """How much a step may raise the total energy without external input (default 1; 0 turns
        the guard off): from the last edit, energy may reach E0 + r (S0 + S/2) plus a push-out
        allowance (physics/step/energy_guard.py); a step beyond it raises SimulationError at the
        'solve' stage and is reverted.  A finite number >= 0 (ValueError otherwise)."""
        return self._energy_guard

    @energy_guard.setter
    def energy_guard(self, value):
        self._energy_guard = finite_num(value, "energy_guard", lo=0.0)
        self._pipeline.dirty = True

    @property
    def time(self) -> float:
        """Simulated time in seconds since the world was created (or loaded): dt summed over the steps
        taken. Settable: finite and >= 0 (ValueError naming 'time' otherwise)."""
        return self._time

    @time.setter
    def time(self, value):
        self._time = finite_num(value, "time", lo=0.0)

    @property
    def gravity(self) -> tuple[float, float]:
        """Gravitational acceleration (m/s^2) as (x, y); default (0, -9.81). Changing it wakes every body (setting the value it has changes nothing). ValueError for a non-finite or malformed pair."""
        return (float(self._gravity[0]), float(self._gravity[1]))

    @gravity.setter
    def gravity(self, value):
        g = finite_vec(value, "gravity")
        same = getattr(self, "_gravity", None) is not None and bool(np.array_equal(g, self._gravity))
        self._gravity = g
        self._pipeline.dirty = True
        if not same:
            self.wake_all()

    @property
    def metadata(self) -> Metadata:
        """What the scene file says of itself (name, description, camera, the sandbox's colours);
        saving writes it back.  A dict whose scene keys are checked when set (physics/metadata.py):
        ValueError names a value a scene file could not hold.  Assigning a dict checks it too."""
        return self._metadata

    @metadata.setter
    def metadata(self, value):
        if not isinstance(value, dict):
            raise ValueError(f"metadata: expected a dict, got {type(value).__name__}")
        self._metadata = Metadata(value)

    @property
    def dt(self) -> float:
        """Length of one step(), in seconds: finite, >= DT_MIN (1e-9 s: below it 1/dt and the sub-step
        rates leave the float range) and <= DT_MAX (3600 s); ValueError naming dt otherwise. A sudden change keeps the warm start when it
        is small (impulses rescaled) and drops it when the step grows more than 4x."""
        return self._dt

    @dt.setter
    def dt(self, value):
        self._dt = finite_num(value, "dt", lo=DT_MIN, hi=DT_MAX)

    @property
    def solver(self) -> str:
        """Name of the solver mode (one of physics.solvers_available(); default "soft_step"). Switching keeps the bodies, contacts' impulses (rescaled to the new mode) and each mode's own settings, and wakes the world. ValueError for an unknown name."""
        return self._solver_name

    @solver.setter
    def solver(self, name):
        if hasattr(self, "_in_callback"):
            self._check_editable("solver")
        mode = solvers.get(name)  # ValueError for an unknown name, ImportError for a broken module
        switched = getattr(self, "_solver_name", name) != name
        self._solver_name = name
        self._mode = mode
        self._settings_store(name)
        if switched:  # a sleeping pile would hide what the new mode does with it
            self.wake_all()
        self._pipeline.invalidate()

    @property
    def solvers(self) -> list[str]:
        """Every solver mode the core has."""
        return solvers.available()

    def _settings_store(self, solver: str) -> ModeValues:
        vals = self._settings.get(solver)
        if vals is None:
            mode = solvers.get(solver)
            vals = self._settings[solver] = ModeValues(mode.settings, lambda v: self._pipeline.fitted(self, mode))
        return vals

    @property
    def settings(self) -> ModeSettings:
        """The current solver's parameters: ``world.settings["substeps"] = 8``."""
        return ModeSettings(self._settings_store(self._solver_name), self._solver_name)

    def settings_for(self, solver: str) -> ModeSettings:
        """The parameters of any solver mode (kept while another mode runs)."""
        return ModeSettings(self._settings_store(solver), solver)

    @property
    def integrator(self) -> str:
        """The seed modes' time integrator ("symplectic_euler", "verlet", "rk4", ...: physics.options.INTEGRATORS). ValueError for an unknown name."""
        return self._integrator

    @integrator.setter
    def integrator(self, name):
        options.code(options.INTEGRATORS, name, "integrator")
        self._integrator = name
        self._pipeline.dirty = True
        if hasattr(self, "_mode"):  # World() checks once its solver is set
            self._say_unused_integrator()

    def _say_unused_integrator(self) -> None:
        """A UserWarning when the integrator set has no effect in the current mode (kept, since a
        switch to a mode that uses it is allowed at any time; ``info()["integrator_used"]`` says
        it too)."""
        why = solvers.unused_integrator(self._solver_name, self._integrator)
        if why is not None:
            warnings.warn(why, UserWarning, stacklevel=3)

    @property
    def broadphase(self) -> str:
        """Broad-phase algorithm ("sweep", "quadtree", "brute": physics.options.BROADPHASES). Same pairs whichever is chosen; ValueError for an unknown name."""
        return self._broadphase

    @broadphase.setter
    def broadphase(self, name):
        options.code(options.BROADPHASES, name, "broad phase")
        self._broadphase = name

    @property
    def narrowphase(self) -> str:
        """Narrow-phase algorithm for polygon pairs ("sat" or "gjk": physics.options.NARROWPHASES). ValueError for an unknown name."""
        return self._narrowphase

    @narrowphase.setter
    def narrowphase(self, name):
        options.code(options.NARROWPHASES, name, "narrow phase")
        self._narrowphase = name
        self._pipeline.dirty = True

    @property
    def threads(self) -> int:
        """Threads a step may use (default: every core numba can use here, 1 without an OpenMP
        or TBB threading layer: physics/threads.py).  A large scene's contact colours, bodies and
        manifolds are split between them; any count gives the same numbers bit for bit.
        ValueError outside 1..the cores numba can use."""
        return self._threads

    @threads.setter
    def threads(self, n):
        self._threads = threads.check(n)
        self._pipeline.dirty = True

    @property
    def sleeping(self) -> bool:
        """Whether resting islands fall asleep (default True). Turning it off wakes every body."""
        return self._sleeping

    @sleeping.setter
    def sleeping(self, on):
        on = flag(on, "sleeping")
        self._sleeping = on
        self._pipeline.dirty = True
        if not on:
            self.wake_all()

    @property
    def profile(self) -> dict:
        """Seconds per stage of the last step (begin, broadphase, narrowphase, solve, islands,
        finish) and their sum (``step``), like Box2D's b2Profile."""
        return self._pipeline.profile.as_dict()

    # -- stepping -----------------------------------------------------------
    def step(self, dt: float | None = None) -> None:
        """Advance the world by ``dt`` (default ``world.dt``).

        Raises :class:`SimulationError` (and leaves the world as it was before the
        step) if the step would produce a non-finite value.
        """
        if self._in_callback:  # (_check_editable, inline: this runs at every step)
            self._check_editable("step")
        h = self._dt if dt is None else finite_num(dt, "dt", lo=DT_MIN, hi=DT_MAX)
        if not math.isfinite(self._time + h):
            raise ValueError(f"dt: a step of {h!r} s would take world.time ({self._time!r} s) beyond the float range")
        self._pipeline.step(self, h)

    def _check_editable(self, what: str) -> None:
        """RuntimeError while a callback runs inside step(): the step holds rows, slots and pairs
        that an added or removed body, fixture, spring or joint would invalidate."""
        if self._in_callback:
            raise RuntimeError(f"{what}: the world cannot be changed from inside a callback (pair_filter "
                               "runs during step()); note the change and make it after step() returns")

    def info(self) -> dict:
        """Counts, solver and the pipeline stages this world runs."""
        return self._pipeline.info(self)

    # -- views and queries ----------------------------------------------------
    def state(self) -> np.ndarray:
        """Every body's state as a read-only numpy structured array (a copy), in body order.

        Fields: ``id`` (int64), ``position`` (2: the body origin, m), ``angle`` (rad),
        ``velocity`` (2: of the centre of mass, m/s), ``angular_velocity`` (rad/s), ``awake``
        (bool).  ``world.state()["position"]`` equals ``[b.position for b in world.bodies]``.
        """
        return views.state(self)

    def contacts(self) -> list[Contact]:
        """Touching contacts of the last step (normal from body_a to body_b, depth > -slop)."""
        return views.contacts(self)

    def contact_depths(self) -> np.ndarray:
        """Depth (m) of each touching contact of the last step, in ``contacts()`` order: the
        same numbers as ``[c.depth for c in world.contacts()]``, as one numpy array and cheap
        enough to read every frame (no Python object per contact)."""
        return views.contact_depths(self)

    def query_point(self, point) -> Body | None:
        """The topmost (last added) body containing a world point, or None."""
        return views.query_point(self, finite_vec(point, "point"))

    def render_data(self) -> RenderData:
        """Arrays for drawing (views into the world's state: read, do not write)."""
        return views.render_data(self)

    def quadtree_cells(self) -> np.ndarray:
        """Rectangles (K, 4: min x, min y, max x, max y) of the broad phase's quadtree over the
        current AABBs, for debug overlays (built on demand; stepping does not need it)."""
        from .collision.broadphase import quadtree_cells
        self._pipeline.refresh_geometry(self)
        return quadtree_cells(self._bodies.view, self._bodies.n)

    def kinetic_energy(self) -> float:
        """Kinetic energy of the dynamic bodies (J)."""
        return measures.kinetic_energy(self)

    def potential_energy(self) -> float:
        """Gravitational (relative to the origin) plus elastic energy of the springs (J)."""
        return measures.potential_energy(self)

    def linear_momentum(self) -> tuple[float, float]:
        """Total linear momentum of the dynamic bodies (kg m/s)."""
        return measures.linear_momentum(self)

    def angular_momentum(self, about=(0.0, 0.0)) -> float:
        """Total angular momentum of the dynamic bodies about a world point (kg m^2/s)."""
        return measures.angular_momentum(self, finite_vec(about, "about"))

    def save_scene(self, path, name: str | None = None, description: str | None = None) -> None:
        """Write this world as a scene file (atomically: temp file + rename); errors as
        ``physics.save_scene`` (OSError, ValueError naming a field, TypeError for the path)."""
        from .scene.save import save_scene  # lazy, and save imports nothing that imports world
        save_scene(self, path, name=name, description=description)

    def __repr__(self):
        return (f"<World {self._bodies.n} bodies, {self._springs.n} springs, solver={self._solver_name}, "
                f"t={self.time:.3f}>")
