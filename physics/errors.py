"""Exceptions of the public API."""


class SimulationError(RuntimeError):
    """A step produced a non-finite value; the world was reverted to the state before it.

    ``bodies`` names the bodies whose state went non-finite, ``stage`` the pipeline stage
    that produced it.
    """

    def __init__(self, message: str, bodies=(), stage: str = ""):
        super().__init__(message)
        self.bodies = list(bodies)
        """Names (or ids) of the bodies whose state went non-finite or gained energy."""
        self.stage = stage
        """The pipeline stage that produced the bad state (e.g. "solve", "integrate")."""


class SceneError(ValueError):
    """A scene file (or scene data) is invalid.  ``problems`` lists (json_path, reason)."""

    def __init__(self, message: str, problems=(), path=None):
        super().__init__(message)
        self.problems = list(problems)
        """Every problem found, as (json_path, reason) pairs, e.g. ("bodies[3].density", "must be > 0")."""
        self.path = path
        """The scene file the problems are in (None for scene data given in memory)."""
