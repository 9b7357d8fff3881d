"""Solver configurations the benchmark runs: each mode's defaults and the settings it sweeps.

A ``Config`` is plain data (mode name, settings dict, label), so a case that carries one runs
the same in any process.
"""
from __future__ import annotations

import dataclasses

DEFAULT_MODE = "soft_step"
QUICK_MODES = ("soft_step", "sequential_impulse")


@dataclasses.dataclass(frozen=True)
class Config:
    """One solver configuration: ``mode`` (a solver name), ``settings`` (overrides of that mode's
    defaults), ``label`` (for tables), ``default`` (no overrides), ``integrator`` (None: the
    world's)."""
    mode: str
    settings: dict
    label: str
    default: bool = False
    integrator: str | None = None


# one setting changed at a time from each mode's defaults
SWEEPS = {
    "soft_step": [{"substeps": 1}, {"substeps": 2}, {"substeps": 8}, {"iterations": 2}, {"relax": False},
                  {"warm_starting": False}, {"block_solver": False},
                  {"solver_layout": "coloured"}],  # issue 17: the coloured, vectorised contact solve
    "sequential_impulse": [{"velocity_iterations": 4}, {"velocity_iterations": 16}, {"velocity_iterations": 32},
                           {"position_correction": "baumgarte"}, {"warm_starting": False}, {"block_solver": False}],
    "impulse": [{"iterations": 5}, {"iterations": 20}, {"projection": "nonlinear"}, {"projection": "none"}],
    "penalty": [{"contact_hertz": 50.0}],
    "hybrid": [{"iterations": 5}, {"projection": "none"}],
}


def generic_sweep(decl) -> list[dict]:
    """Up to five one-setting variations for a mode SWEEPS does not list: iteration and sub-step
    counts halved and doubled (within the declared range), every other choice of a string."""
    out = []
    for k, s in decl.items():
        if isinstance(s.default, bool):
            continue
        if isinstance(s.default, int) and any(w in k for w in ("iter", "substep")):
            for v in (max(s.lo or 1, s.default // 2), min(s.hi or 1e9, s.default * 2)):
                if v != s.default:
                    out.append({k: int(v)})
        elif isinstance(s.default, str):
            out += [{k: c} for c in s.choices if c != s.default]
    return out[:5]


def configs_for(mode, quick=False) -> list[Config]:
    """The defaults of ``mode`` first, then (unless ``quick``) its sweep; settings the mode does
    not declare are dropped.  ValueError (from physics.solvers) for an unknown mode."""
    from physics import solvers
    decl = solvers.get(mode).settings
    cfgs = [Config(mode, {}, mode, default=True)]
    if quick:
        return cfgs
    for var in SWEEPS.get(mode) or generic_sweep(decl):
        var = {k: v for k, v in var.items() if k in decl}
        if not var:
            continue
        label = mode + " " + " ".join(f"{k}={v}" for k, v in var.items())
        cfgs.append(Config(mode, var, label))
    return cfgs


def available_modes() -> list[str]:
    """Every solver mode this build of physics offers."""
    import physics
    return physics.solvers_available()


def uses_integrator(mode) -> bool:
    """Whether ``mode`` honours ``world.integrator`` (the seed modes do; the others integrate
    inside their own step)."""
    from physics import solvers
    return bool(getattr(solvers.get(mode), "uses_integrator", False))
