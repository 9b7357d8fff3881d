"""Solver modes: one module per mode behind one small interface.

A mode integrates forces, resolves contacts and springs, and integrates
positions for one step.  Collision detection happens before it (shared by
all modes), islands and the finite check after it.  Switching mode mid-run
is switching which object's ``step`` the world calls; contact arrays,
warm-start impulses and body state are shared.
"""
from __future__ import annotations

import importlib

from ..options import SOLVERS
from ..settings import Setting


class SolverMode:
    """Interface of a solver mode (subclass and register in ``_REGISTRY``)."""

    name: str = ""
    description: str = ""
    settings: dict[str, Setting] = {}
    #: the world's integrator setting applies to this mode
    uses_integrator: bool = False

    def step(self, world, dt: float, params: dict) -> None:
        """Advance bodies by ``dt``: forces, contacts (world._contacts.cur), springs, positions."""
        raise NotImplementedError

    def stages(self, world) -> list[str]:
        """Names of the stages this mode runs for this world (for ``info``)."""
        return [self.name]


# mode name -> "module:Class"; imported on first use so one broken mode never breaks the rest
_REGISTRY = {
    "soft_step": "physics.solvers.soft_step:SoftStep",
    "sequential_impulse": "physics.solvers.sequential_impulse:SequentialImpulse",
    "impulse": "physics.solvers.impulse:ImpulseMode",
    "penalty": "physics.solvers.penalty:PenaltyMode",
    "hybrid": "physics.solvers.hybrid:HybridMode",
}
assert tuple(_REGISTRY) == SOLVERS, "physics/options.py names the modes"
_CACHE: dict[str, SolverMode] = {}


def available() -> list[str]:
    """Names of the modes whose modules exist, in registry order."""
    out = []
    for name in _REGISTRY:
        try:
            get(name)
        except (ImportError, AttributeError):
            continue
        out.append(name)
    return out


def get(name: str) -> SolverMode:
    if name not in _CACHE:
        if name not in _REGISTRY:
            raise ValueError(f"unknown solver '{name}'; choose one of {list(_REGISTRY)}")
        mod, cls = _REGISTRY[name].split(":")
        _CACHE[name] = getattr(importlib.import_module(mod), cls)()
    return _CACHE[name]
