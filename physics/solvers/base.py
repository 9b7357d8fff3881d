"""The interface every solver mode implements."""
from __future__ import annotations

from ..settings import Setting


class SolverMode:
    """A solver mode: integrates forces, resolves contacts and springs, moves the bodies.

    Collision detection runs before it (shared by all modes), islands and the
    finite check after it.  The pipeline hands ``step`` the step context
    (physics/step/context.py), the mode's parameter record (its ``settings``
    plus the ``derived`` fields ``derive`` fills) and the world's store
    (physics/store: bodies, verts, springs, contacts).  Switching mode mid-run is
    switching which mode's ``step`` runs; body and contact tables are shared.
    """

    name: str = ""
    description: str = ""
    settings: dict[str, Setting] = {}
    #: extra fields of the parameter record: (name, dtype) or (name, dtype, shape)
    derived: tuple = ()
    #: the settings fields of the parameter record, when modes share one record type (a union of
    #: their settings; the fields a mode lacks keep their defaults); None: ``settings``
    record: dict | None = None
    #: the world's integrator setting applies to this mode
    uses_integrator: bool = False
    #: how a mode that does not use the setting integrates: the integrator's name and in words
    integration: tuple = ("symplectic_euler", "symplectic Euler")

    def derive(self, ctx, par, store) -> None:
        """Fill the derived fields of ``par`` for this step (called before ``step``)."""

    def step(self, ctx, par, store) -> None:
        """Advance bodies by ctx.dt: forces, contacts (store.contacts.cur), springs, positions."""
        raise NotImplementedError

    def fit(self, world) -> dict:
        """Settings the scene's content calls for, with the reason: name -> (value, why).  The
        world runs with them where the user set nothing (physics/settings.py ModeValues); it asks
        again after every edit.  Deterministic: a function of the world's bodies and shapes."""
        return {}

    def push_speed(self, values: dict) -> float:
        """The largest speed (m/s) at which this mode's contacts push overlap apart, with its
        settings ``values``: the energy guard allows each overlapping contact the energy of
        leaving at it (physics/step/energy_sums.push_sum).  0: the mode pushes overlap out by
        moving positions only, which leaves no speed behind."""
        return 0.0

    def stages(self, store, values: dict, integrator: str) -> list[str]:
        """Names of the stages this mode runs (for ``World.info``); ``values``: its settings."""
        return [self.name]
