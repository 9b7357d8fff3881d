"""Bounds the sandbox puts on world fields beyond the core's (finite numbers), in the user's
terms: a value that would eject every body at the first step is refused where it was typed."""
from __future__ import annotations

import math

#: m/s^2 per component: 100 g, beyond any scene worth watching (1e12 threw every body out at once)
GRAVITY_MAX = 1000.0


def checked_gravity(g) -> tuple:
    """``g`` as (gx, gy) if both components are finite and within GRAVITY_MAX; ValueError saying
    the field, the range and the typed value otherwise."""
    gx, gy = (float(v) for v in g)
    if not all(math.isfinite(v) and abs(v) <= GRAVITY_MAX for v in (gx, gy)):
        raise ValueError(f"gravity: each component must be between {-GRAVITY_MAX:g} and {GRAVITY_MAX:g} m/s² "
                         f"(got {gx:g}, {gy:g})")
    return gx, gy
