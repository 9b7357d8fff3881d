"""The names a user can choose between: solver modes, integrators, broad and narrow phases.

One list each, imported by the world (validation), the collision and solver
stages (dispatch), the scene schema, the sandbox's panels, the benchmark and the
tests, so a name is added or renamed in one place.  Codes are the positions in
these tuples; kernels receive the codes.
"""
from __future__ import annotations

from .validate import shown

#: solver modes, default first (physics/solvers/)
SOLVERS = ("soft_step", "sequential_impulse", "impulse", "penalty", "hybrid")
DEFAULT_SOLVER = "soft_step"

#: one line each: what the mode is, what it is good and bad at (from docs/reliability.md)
SOLVER_SUMMARIES = {
    "soft_step": "Sub-stepped soft contacts with relax and restitution (Box2D v3 style); holds tall "
                 "stacks and fast impacts; the default.",
    "sequential_impulse": "Rigid contacts by projected Gauss-Seidel with warm starting (Box2D 2.x / "
                          "Chipmunk style); good stacks, weaker at large mass ratios.",
    "impulse": "The seed report's impulses with projection; exact bounces and friction, but tall "
               "stacks collapse.",
    "penalty": "The seed report's penalty springs, sub-stepped; smooth resting contact, soft impacts, "
               "slow on big scenes.",
    "hybrid": "The seed report's impulses for impacts and penalty springs for resting contact; "
              "bounces well, weak for tall stacks.",
}

#: force integrators of the seed report's modes (impulse, penalty, hybrid)
INTEGRATORS = ("euler", "symplectic_euler", "rk4")
DEFAULT_INTEGRATOR = "symplectic_euler"

#: broad phases; "auto" picks brute force or sort-and-sweep by body count
BROADPHASES = ("auto", "sweep", "quadtree", "brute")
DEFAULT_BROADPHASE = "auto"

#: narrow phases for polygon pairs
NARROWPHASES = ("sat", "gjk")
DEFAULT_NARROWPHASE = "sat"


def code(names: tuple, name: str, what: str) -> int:
    """The code (index) of ``name`` in ``names``, or ValueError naming ``what`` and the choices."""
    if isinstance(name, str) and name in names:
        return names.index(name)
    raise ValueError(f"unknown {what} {shown(name)}; choose one of {list(names)}")
