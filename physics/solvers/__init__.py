"""Solver modes, one package per family, behind one small interface (solvers/base.py).

- ``soft_step``: sub-stepped soft contacts (Box2D v3 style), the default;
- ``sequential_impulse``: projected Gauss-Seidel with warm starting (Box2D 2.x style);
- ``classic``: the seed report's impulse, penalty and hybrid modes with their
  explicit integrators and force generators.

Each family is a small package on top of physics/constraints/.  Modes are
imported on first use, so one broken mode never breaks the rest.
"""
from __future__ import annotations

import importlib

from ..options import SOLVERS
from ..validate import shown
from .base import SolverMode

# mode name -> "module:Class"
_REGISTRY = {
    "soft_step": "physics.solvers.soft_step.mode:SoftStep",
    "sequential_impulse": "physics.solvers.sequential_impulse.mode:SequentialImpulse",
    "impulse": "physics.solvers.classic.impulse:ImpulseMode",
    "penalty": "physics.solvers.classic.penalty:PenaltyMode",
    "hybrid": "physics.solvers.classic.hybrid:HybridMode",
}
assert tuple(_REGISTRY) == SOLVERS, "physics/options.py names the modes"
_CACHE: dict[str, SolverMode] = {}

__all__ = ["SolverMode", "available", "get", "unused_integrator"]


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
    """The mode called ``name`` (ValueError for an unknown name, ImportError for a broken module)."""
    if not isinstance(name, str) or name not in _REGISTRY:
        raise ValueError(f"unknown solver {shown(name)}; choose one of {list(_REGISTRY)}")
    if name not in _CACHE:
        mod, cls = _REGISTRY[name].split(":")
        _CACHE[name] = getattr(importlib.import_module(mod), cls)()
    return _CACHE[name]


def unused_integrator(solver: str, integrator: str) -> str | None:
    """Why ``integrator`` has no effect in ``solver``, in words, or None when it has one (the mode
    uses the world's integrator, or ``integrator`` is how the mode integrates anyway)."""
    mode = get(solver)
    if mode.uses_integrator or integrator == mode.integration[0]:
        return None
    users = [n for n in _REGISTRY if n != solver and get(n).uses_integrator]
    return (f"integrator {integrator!r} is not used by solver {solver!r}, which integrates its own way "
            f"({mode.integration[1]}); the setting is kept for the modes that use it ({', '.join(users)})")
