"""The settings the tuner tries: a coarse grid per mode, then refinements of the good ones.

Round one walks each mode's main accuracy knob (sub-steps, iterations, penalty
stiffness) and the time step as a multiple of the scene's.  Round two takes
only the candidates on the speed/error Pareto front of round one and tries
their secondary settings (relax, block solver, iterations per sub-step, contact
hertz, position iterations, projection, integrator) and the next finer or
coarser level of the main knob: a candidate dominated in both speed and error
is not refined further (issue 19, "pruned as it goes").  Every value is one the
mode declares (physics/settings.py), checked against its range here.
"""
from __future__ import annotations

from .runs import Candidate

#: the main accuracy knob of each mode and the levels round one tries
MAIN = {
    "soft_step": ("substeps", (1, 2, 4, 8, 16)),
    "sequential_impulse": ("velocity_iterations", (2, 4, 8, 16, 32)),
    "impulse": ("iterations", (3, 10, 30)),
    "penalty": ("contact_hertz", (10.0, 25.0, 60.0)),
    "hybrid": ("iterations", (3, 10, 30)),
}
#: secondary variants round two tries on a front candidate: (setting, value) pairs
SECONDARY = {
    "soft_step": (("relax", False), ("block_solver", False), ("iterations", 2), ("contact_hertz", 30.0),
                  ("contact_hertz", 120.0), ("warm_starting", False)),
    "sequential_impulse": (("position_iterations", 0), ("position_iterations", 8), ("block_solver", True)),
    "impulse": (("projection", "nonlinear"), ("projection_iterations", 1), ("integrator", "rk4")),
    "penalty": (("integrator", "rk4"), ("damping_ratio", 0.5)),
    "hybrid": (("integrator", "rk4"), ("contact_hertz", 60.0)),
}
#: time steps (multiples of the scene's) round one tries at each mode's default settings
DT_ROUND_ONE = (0.5, 2.0)
#: the reference: soft_step, many sub-steps, a quarter of the scene's dt; the check run halves dt
REFERENCE = Candidate("soft_step", (("iterations", 2), ("substeps", 8)), 0.25)
FINE = Candidate("soft_step", (("iterations", 2), ("substeps", 8)), 0.125)


def declared(solver: str) -> dict:
    """The mode's declared settings {name: Setting} (physics/settings.py)."""
    from ..solvers import get
    return dict(get(solver).settings)


def valid(cand: Candidate) -> bool:
    """Whether every setting of ``cand`` is declared by its mode and inside its range."""
    decl = declared(cand.solver)
    for k, v in cand.settings:
        s = decl.get(k)
        if s is None:
            return False
        try:
            s.coerce(v)
        except ValueError:
            return False
    return True


def round_one(modes) -> list[Candidate]:
    """Each mode's main knob at its levels, and the mode's defaults at the DT_ROUND_ONE steps."""
    out = []
    for m in modes:
        knob, levels = MAIN[m]
        out += [Candidate(m, ((knob, v),)) for v in levels]
        out += [Candidate(m, (), f) for f in DT_ROUND_ONE]
    return [c for c in out if valid(c)]


def round_two(front: list[Candidate]) -> list[Candidate]:
    """Refinements of the front candidates: secondary settings, and the neighbour levels of the
    main knob between round one's (geometric means, rounded for integer settings)."""
    out = []
    for c in front:
        for k, v in SECONDARY.get(c.solver, ()):
            out.append(c.with_settings(integrator=v) if k == "integrator" else c.with_settings(**{k: v}))
        knob, levels = MAIN[c.solver]
        cur = dict(c.settings).get(knob, declared(c.solver)[knob].default)
        for other in levels:
            if other == cur:
                continue
            mid = (cur * other) ** 0.5
            mid = int(round(mid)) if isinstance(cur, int) else round(mid, 1)
            if mid not in (cur, other) and min(cur, other) < mid < max(cur, other):
                out.append(c.with_settings(**{knob: mid}))
        if c.dt_factor == 1.0:
            out += [c.with_settings(dt_factor=f) for f in DT_ROUND_ONE]
    seen, unique = {c.key for c in front}, []
    for c in out:
        if valid(c) and c.key not in seen:
            seen.add(c.key)
            unique.append(c)
    return unique


def pareto(rows: list[dict]) -> list[dict]:
    """The rows no other row beats in both ``seconds`` and ``error`` (finished runs only)."""
    ok = sorted((r for r in rows if r["error"] == r["error"] and r["error"] != float("inf")),
                key=lambda r: (r["seconds"], r["error"]))
    front, best = [], float("inf")
    for r in ok:
        if r["error"] < best:
            front.append(r)
            best = r["error"]
    return front
