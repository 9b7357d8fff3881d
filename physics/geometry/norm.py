"""The length of a 2-D vector where the step needs it per pair or per body.

glibc's ``hypot`` is correctly rounded and guards against overflow and underflow, at the price
of a library call of tens of ns; called twice per contact pair and once per fixture and step,
it was a large pile's costliest library call (docs/benchmarks.md, "Where a step goes").
``sqrt(x^2 + y^2)`` is within one rounding of it wherever the squares neither overflow nor
underflow; outside that range (a zero vector too) ``hypot`` answers.  Used where the length
only sets a margin or a threshold, never where it becomes a result.
"""
from __future__ import annotations

import math

from .._jit import kernel

_BIG = 1e300    # below this the squares' sum cannot overflow (each square < 1e300)
_SMALL = 1e-290  # above this it has not lost digits to underflow


@kernel(forceinline=True)
def length(x, y):
    """|(x, y)| (math.hypot's value to within one rounding; NaN for a NaN component)."""
    s = x * x + y * y
    if _SMALL < s < _BIG:
        return math.sqrt(s)
    return math.hypot(x, y)
