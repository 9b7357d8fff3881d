"""Shared pieces of the extremes suite: the scenarios live in bench/scenarios/extremes/ (the
table in docs/reliability.md runs the same ones, judged by bench/reliability), the tests assert
their own bounds on the scenarios' figures; test_pinned_scenarios.py notices any change to them."""

import physics

MODES = physics.solvers_available()
# the modes whose claims the issue names: rigid contacts with speculative (continuous) collision
CONTINUOUS = [m for m in ("soft_step", "sequential_impulse") if m in MODES]


def integrators(mode):
    """The integrators a mode honours (None: the mode has its own)."""
    return ["euler", "symplectic_euler", "rk4"] if physics.solvers.get(mode).uses_integrator else [None]
