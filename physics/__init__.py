"""Stelkropp's physics core: a data-oriented 2D rigid-body engine compiled with numba.

    import physics
    world = physics.World(gravity=(0.0, -9.81), dt=1/60, solver="soft_step")
    ground = world.add_body(physics.Polygon.box(40, 1), kind="static", position=(0, -0.5))
    box = world.add_body(physics.Polygon.box(1, 1), position=(0, 2))
    world.step()
"""
from . import _jit  # noqa: F401  (configures numba's cache before any kernel is defined)
from .body import Body
from .errors import SceneError, SimulationError
from .events import ContactBeginEvent, ContactEvents, ContactHitEvent, SensorEvents
from .fixture import Fixture
from .geometry.capsule import Capsule, Segment
from .geometry.chain import Chain, ChainSegment
from .geometry.decompose import decompose
from .geometry.shapes import Circle, Polygon
from .joint import Joint
from . import joint_kinds
from .joint_kinds import *  # (the kinds' classes: RevoluteJoint, ..., joint_kinds.__all__)
from .queries.hits import RayHit, ShapeHit
from .spring import Spring
from .world import World

__all__ = ["World", "Body", "Fixture", "Spring", "Joint", "RayHit", "ShapeHit", "Polygon", "Circle", "Capsule", "Segment", "Chain", "ChainSegment", "decompose", "SceneError", "SimulationError",
           "ContactEvents", "ContactBeginEvent", "ContactHitEvent", "SensorEvents",
           "load_scene", "save_scene", "solvers_available", "tune", "precompile"] + joint_kinds.__all__


def load_scene(path):
    """Load a scene file (JSON) into a new World; raises SceneError listing every problem."""
    from .scene import load_scene as _load
    return _load(path)


def save_scene(world, path, name=None, description=None) -> None:
    """Write ``world`` as a scene file (JSON), atomically; ``name``/``description`` override the
    world's metadata in the file.  Raises OSError if it cannot be written or ``path`` is a folder,
    FIFO or device, ValueError naming the field if the scene could not be loaded again, TypeError
    for a path that is no str, bytes or os.PathLike; the old file is then kept."""
    from .scene.save import save_scene as _save
    _save(world, path, name=name, description=description)


def precompile(what=None, jobs: int = 1, progress=None):
    """Compile the kernels ``what`` needs into numba's disk cache before the first step.

    ``what``: a World (what its next step needs), a solver mode name or a list of them (every
    kernel of those modes), or None for all.  ``jobs``: worker processes sharing the cache (the
    machine's cores: ``physics.compile_units.default_jobs()``).  ``progress``: called with one line per
    finished unit (default: printed to stderr).  Returns ``[(unit, wall s, CPU s), ...]``.  Also
    ``python -m physics precompile [SCENE ...] [--mode M] [--jobs N]``.
    """
    from .compile_units import precompile as _pre
    return _pre(what, jobs=jobs, progress=progress)


def solvers_available() -> list[str]:
    """Names of the solver modes this build has (the values ``World.solver`` accepts).

    >>> import physics
    >>> "soft_step" in physics.solvers_available()
    True
    """
    from .solvers import available
    return available()


def tune(source, steps=600, metric="trajectory", budget=0.01, scheduler=None, modes=None, progress=True,
         results=None, resume=False, cancel=None, on_progress=None):
    """The fastest solver mode and settings whose error on ``source`` (a World, scene data or a scene
    file) stays within ``budget`` over ``steps`` steps; see physics.tuning.search.tune (returns a
    TuneResult: rows, front, choice, fragment; ValueError for a bad steps/metric/budget/scheduler;
    ``cancel``/``on_progress``: a stop check and a progress callback, physics.tuning.Cancelled)."""
    from .tuning import tune as _tune
    return _tune(source, steps=steps, metric=metric, budget=budget, scheduler=scheduler, modes=modes,
                 progress=progress, results=results, resume=resume, cancel=cancel, on_progress=on_progress)
