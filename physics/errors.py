"""Exceptions of the public API."""


class SimulationError(RuntimeError):
    """A step produced a non-finite value; the world was reverted to the state before it.

    ``bodies`` names the bodies whose state went non-finite, ``stage`` the pipeline stage
    that produced it.
    """

    def __init__(self, message: str, bodies=(), stage: str = ""):
        super().__init__(message)
        self.bodies = list(bodies)
        self.stage = stage


class SceneError(ValueError):
    """A scene file (or scene data) is invalid.  ``problems`` lists (json_path, reason)."""

    def __init__(self, message: str, problems=(), path=None):
        super().__init__(message)
        self.problems = list(problems)
        self.path = path
