"""Shared pieces of the extremes suite: the probes live in bench/reliability.py (the table in
docs/reliability.md is generated from the same functions), the tests assert their figures."""
import pytest

import physics

MODES = physics.solvers_available()
# the modes whose claims the issue names: rigid contacts with speculative (continuous) collision
CONTINUOUS = [m for m in ("soft_step", "sequential_impulse") if m in MODES]


def integrators(mode):
    """The integrators a mode honours (None: the mode has its own)."""
    return ["euler", "symplectic_euler", "rk4"] if physics.solvers.get(mode).uses_integrator else [None]


def known_bug(reason):
    """A probe that fails because of an engine bug named in issue 9's report; strict, so the test
    turns red (XPASS) when the bug is fixed and the marker must go."""
    return pytest.mark.xfail(strict=True, reason=reason)
