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
from .shapes import Circle, Polygon
from .spring import Spring
from .world import World

__all__ = ["World", "Body", "Spring", "Polygon", "Circle", "SceneError", "SimulationError",
           "load_scene", "solvers_available"]


def load_scene(path):
    """Load a scene file (JSON) into a new World; raises SceneError listing every problem."""
    from .scene import load_scene as _load
    return _load(path)


def solvers_available() -> list[str]:
    from .solvers import available
    return available()
