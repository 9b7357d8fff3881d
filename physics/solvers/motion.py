"""Integration of body motion inside the sub-stepped solvers (symplectic Euler).

Velocities first (gravity and user forces on awake dynamic bodies), then
positions with the new velocities: the semi-implicit order that keeps
orbits and oscillators from gaining energy.  Rotation per sub-step is
capped so a spinning sliver cannot tunnel through its own contacts.
"""
from __future__ import annotations

import math

from .._jit import kernel
from ..store import DYNAMIC, STATIC

MAX_ROTATION = 0.25 * math.pi


@kernel
def integrate_velocities(B, n, gx, gy, h):
    for i in range(n):
        if B.kind[i] != DYNAMIC or B.awake[i] == 0:
            continue
        B.v[i, 0] += h * (gx + B.inv_m[i] * B.f[i, 0])
        B.v[i, 1] += h * (gy + B.inv_m[i] * B.f[i, 1])
        B.w[i] += h * B.inv_i[i] * B.tau[i]


@kernel
def integrate_positions(B, n, h, DP, DQ, DC, DS):
    """x += h v, q += h w; accumulates the displacement since the step began."""
    for i in range(n):
        if B.kind[i] == STATIC or B.awake[i] == 0:
            continue
        w = B.w[i]
        if abs(w * h) > MAX_ROTATION:
            w = math.copysign(MAX_ROTATION / h, w)
            B.w[i] = w
        dx = h * B.v[i, 0]
        dy = h * B.v[i, 1]
        B.x[i, 0] += dx
        B.x[i, 1] += dy
        B.q[i] += h * w
        DP[i, 0] += dx
        DP[i, 1] += dy
        DQ[i] += h * w
        DC[i] = math.cos(DQ[i])
        DS[i] = math.sin(DQ[i])


SMALL_ROTATION = 0.05  # below this (rad per sub-step) sin/cos of the increment by series


@kernel
def integrate_positions_rot(B, n, h, DP, DC, DS):
    """``integrate_positions`` keeping the rotation since the step began as (cos, sin) only.

    B.q still advances by exactly h w; the displacement's (DC, DS) is composed
    with the increment's rotation, whose sin and cos for |h w| < SMALL_ROTATION
    come from their series to within rounding (first omitted terms < 1e-15)
    instead of two libm calls per body and sub-step.
    """
    for i in range(n):
        if B.kind[i] == STATIC or B.awake[i] == 0:
            continue
        w = B.w[i]
        if abs(w * h) > MAX_ROTATION:
            w = math.copysign(MAX_ROTATION / h, w)
            B.w[i] = w
        dx = h * B.v[i, 0]
        dy = h * B.v[i, 1]
        B.x[i, 0] += dx
        B.x[i, 1] += dy
        t = h * w
        B.q[i] += t
        DP[i, 0] += dx
        DP[i, 1] += dy
        if t == 0.0:
            continue
        if abs(t) < SMALL_ROTATION:
            t2 = t * t
            c = 1.0 - t2 * (0.5 - t2 * (1.0 / 24.0 - t2 * (1.0 / 720.0)))
            s = t * (1.0 - t2 * (1.0 / 6.0 - t2 * (1.0 / 120.0 - t2 * (1.0 / 5040.0))))
        else:
            c = math.cos(t)
            s = math.sin(t)
        c0 = DC[i]
        s0 = DS[i]
        DC[i] = c0 * c - s0 * s
        DS[i] = s0 * c + c0 * s


@kernel
def reset_displacements(n, DP, DQ, DC, DS):
    for i in range(n):
        DP[i, 0] = 0.0
        DP[i, 1] = 0.0
        DQ[i] = 0.0
        DC[i] = 1.0
        DS[i] = 0.0
