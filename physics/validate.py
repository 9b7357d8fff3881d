"""Validation of user input: every error is a ValueError that names the field.

Shared by the world, body, spring (and later fixture and joint) handles, so a
rule such as "densities between 1e-6 and 1e9 kg/m^2" lives in one place.
"""
from __future__ import annotations

import math

import numpy as np


def finite_vec(value, field: str) -> np.ndarray:
    try:
        v = np.array(value, dtype=np.float64).reshape(2)
    except (TypeError, ValueError):
        raise ValueError(f"{field}: expected a pair of numbers, got {value!r}") from None
    if not np.all(np.isfinite(v)):
        raise ValueError(f"{field}: must be finite, got {value!r}")
    return v


def finite_num(value, field: str, lo=None, hi=None, lo_open=False) -> float:
    if isinstance(value, bool):
        raise ValueError(f"{field}: expected a number, got {value!r}")
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{field}: expected a number, got {value!r}") from None
    if not math.isfinite(x):
        raise ValueError(f"{field}: must be finite, got {value!r}")
    if lo is not None and (x < lo or (lo_open and x == lo)):
        raise ValueError(f"{field}: must be {'>' if lo_open else '>='} {lo}, got {value!r}")
    if hi is not None and x > hi:
        raise ValueError(f"{field}: must be <= {hi}, got {value!r}")
    return x


# densities (kg/m^2) the solvers are known to handle: a 1e-6 feather on a 1e9 anvil is a mass
# ratio of 1e15, past which no iterative solver transfers a load, and beyond this the inverse
# masses and impulses start to under- or overflow
DENSITY_MIN, DENSITY_MAX = 1e-6, 1e9


def checked_density(value, shape, field: str = "density") -> float:
    """A density that gives ``shape`` a finite, positive mass and inertia, or ValueError naming ``field``."""
    d = finite_num(value, field, lo=0.0, lo_open=True)
    if not DENSITY_MIN <= d <= DENSITY_MAX:
        raise ValueError(f"{field}: must be between {DENSITY_MIN:g} and {DENSITY_MAX:g} kg/m^2, got {value!r}")
    m, _, inertia = shape.mass_properties(d)
    ok = all(math.isfinite(x) and x > 0.0 and math.isfinite(1.0 / x) for x in (m, inertia))
    if not ok:
        raise ValueError(f"{field}: {d:g} kg/m^2 gives this shape mass {m:g} kg and inertia {inertia:g} kg m^2, "
                         "which the solver cannot represent (choose a density or size nearer 1)")
    return d


def friction_pair(value, field: str = "friction") -> tuple[float, float]:
    """``0.6`` -> (0.6, 0.6); ``(static, dynamic)`` or ``{"static", "dynamic"}`` as given."""
    if isinstance(value, dict):
        s, d = value.get("static"), value.get("dynamic")
    elif isinstance(value, (tuple, list, np.ndarray)):
        if len(value) != 2:
            raise ValueError(f"{field}: expected one number or a (static, dynamic) pair, got {value!r}")
        s, d = value
    else:
        s = d = value
    return finite_num(s, f"{field}.static", lo=0.0), finite_num(d, f"{field}.dynamic", lo=0.0)
