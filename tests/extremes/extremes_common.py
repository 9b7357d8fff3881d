"""Shared pieces of the extremes suite: the probes live in bench/reliability.py (the table in
docs/reliability.md is generated from the same functions), the tests assert their figures."""

import physics

MODES = physics.solvers_available()
# the modes whose claims the issue names: rigid contacts with speculative (continuous) collision
CONTINUOUS = [m for m in ("soft_step", "sequential_impulse") if m in MODES]


def integrators(mode):
    """The integrators a mode honours (None: the mode has its own)."""
    return ["euler", "symplectic_euler", "rk4"] if physics.solvers.get(mode).uses_integrator else [None]
