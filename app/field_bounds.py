"""Bounds the sandbox puts on fields beyond the core's (finite numbers), in the user's terms: a
value that would eject every body at the first step, or make the next step's energy overflow
(the step then failed with the world reverted and a message about the solver's stages), is
refused where it was typed."""
from __future__ import annotations

import math

import numpy as np

#: m/s^2 per component: 100 g, beyond any scene worth watching (1e12 threw every body out at once)
GRAVITY_MAX = 1000.0
#: what a body's and a spring's fields may hold: a body at 1e300 m, or moving at 1e300 m/s,
#: overflowed the next step's energy; 1e300 N/m overflowed a spring within half a second (1e15 held)
LIMITS = {"position": (-1e6, 1e6, "m"), "velocity": (-1e4, 1e4, "m/s"),
          "angular_velocity": (-1e4, 1e4, "rad/s"), "stiffness": (0.0, 1e12, "N/m"),
          "rest_length": (0.0, 1e6, "m"), "anchor_a": (-1e6, 1e6, "m"), "anchor_b": (-1e6, 1e6, "m")}


def _said(v: float) -> str:
    # a float field holds up to 3.4e38: a larger number typed arrives as inf
    return f"{v:g}" if math.isfinite(v) else "a number too large to hold"


def within(label: str, value, lo: float, hi: float, unit: str):
    """``value`` (a number or a vector) if every component is finite and in [lo, hi]; ValueError
    saying the field, the range and the typed value otherwise."""
    parts = [float(v) for v in np.atleast_1d(np.asarray(value, dtype=float))]
    if all(math.isfinite(v) and lo <= v <= hi for v in parts):
        return value
    which = "each component must" if len(parts) > 1 else "must"
    raise ValueError(f"{label}: {which} be between {lo:g} and {hi:g} {unit} (got {', '.join(map(_said, parts))})")


def checked(field: str, value, label: str | None = None):
    """``value`` for the body, spring, joint or fixture field ``field`` if within its LIMITS, or
    (fields without one) if its numbers are finite; ValueError in the user's terms otherwise."""
    label = label or field.replace("_", " ")
    if field in LIMITS:
        return within(label, value, *LIMITS[field])
    if value is None or isinstance(value, (str, bool)):
        return value
    try:
        parts = [float(v) for v in np.atleast_1d(np.asarray(value, dtype=float))]
    except (TypeError, ValueError):
        return value                  # not a number: the core says what it takes
    if all(math.isfinite(v) for v in parts):
        return value
    raise ValueError(f"{label}: must be a finite number (got {', '.join(map(_said, parts))})")


def checked_gravity(g) -> tuple:
    """``g`` as (gx, gy) if both components are finite and within GRAVITY_MAX; ValueError saying
    the field, the range and the typed value otherwise."""
    gx, gy = (float(v) for v in g)
    within("gravity", (gx, gy), -GRAVITY_MAX, GRAVITY_MAX, "m/s²")
    return gx, gy
