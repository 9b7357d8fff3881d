"""Softness of a joint's rows for one step, written into the prepared constants.

Rigid equality rows take the mode's joint softness in the biased pass (the
bias that removes drift; Box2D v3's constraint hertz and damping ratio) and
none in the relax pass; rows that are springs on purpose (a weld with a
frequency) keep their own softness in every pass, like the spring rows.
"""
from __future__ import annotations

import math

from .jit import row_inline
from ..softness import softness

PREWARP_LIMIT = 1.2  # omega h beyond which the spring keeps its own frequency (tan grows without bound)


@row_inline
def prewarped(hertz, h):
    """The frequency to give a soft row so that it oscillates at ``hertz`` over steps of ``h``.

    A soft row is implicit Euler on its spring, whose discrete oscillation turns by
    atan(omega h) per step instead of omega h: 5.4 % slow at 4 Hz over a 60 Hz step.
    Asking for omega' = tan(omega h) / h turns it by exactly omega h (frequency
    pre-warping, as in the bilinear transform); past PREWARP_LIMIT it is left alone."""
    t = 2.0 * math.pi * hertz * h
    if t <= 0.0 or t >= PREWARP_LIMIT:
        return hertz
    return math.tan(t) / (2.0 * math.pi * h)
from .layout import SOFT_EQ, SOFT_LIMIT, SOFT_SPRING


@row_inline
def rigid_row(JW, j, r):
    """Equality row r: the joint softness (at SOFT_LIMIT, written first by prepare) when biased,
    rigid when relaxing."""
    F = JW.F
    o = SOFT_EQ + 6 * r
    F[j, o] = F[j, SOFT_LIMIT]
    F[j, o + 1] = F[j, SOFT_LIMIT + 1]
    F[j, o + 2] = F[j, SOFT_LIMIT + 2]
    F[j, o + 3] = 0.0
    F[j, o + 4] = 1.0
    F[j, o + 5] = 0.0


@row_inline
def spring_row(JW, j, r, hertz, zeta, h):
    """Equality row r as a spring of ``hertz`` (soft in every pass); rigid when hertz is 0."""
    if hertz <= 0.0:
        rigid_row(JW, j, r)
        return
    rate, ms, isc = softness(prewarped(hertz, h), zeta, h)
    F = JW.F
    o = SOFT_EQ + 6 * r
    for k in range(2):
        F[j, o + 3 * k] = rate
        F[j, o + 3 * k + 1] = ms
        F[j, o + 3 * k + 2] = isc


@row_inline
def spring_softness(JW, j, hertz, zeta, h):
    """The spring row's softness triple (pre-warped: see ``prewarped``)."""
    rate, ms, isc = softness(prewarped(hertz, h), zeta, h)
    F = JW.F
    F[j, SOFT_SPRING] = rate
    F[j, SOFT_SPRING + 1] = ms
    F[j, SOFT_SPRING + 2] = isc
