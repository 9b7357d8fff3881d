"""Integration of body motion on the body table for sequential impulses (symplectic Euler).

Velocities first (gravity and user forces on awake dynamic bodies), then
positions with the new velocities: the semi-implicit order that keeps
orbits and oscillators from gaining energy.  Rotation per sub-step is
capped (constraints/rotation_cap.py MAX_ROTATION) so a spinning sliver cannot
tunnel through its own contacts.
"""
from __future__ import annotations

import math

from ..._jit import kernel
from ...constraints.rotation_cap import MAX_ROTATION, cap_about_pivot
from ...store import DYNAMIC, STATIC


@kernel
def integrate_velocities(B, n, gx, gy, h):
    for i in range(n):
        if B.kind[i] != DYNAMIC or B.awake[i] == 0:
            continue
        B.v[i, 0] += h * (gx + B.inv_m[i] * B.f[i, 0])
        B.v[i, 1] += h * (gy + B.inv_m[i] * B.f[i, 1])
        B.w[i] += h * B.inv_i[i] * B.tau[i]


@kernel
def integrate_positions(B, n, h, DP, DQ, DC, DS, PV, npv):
    """x += h v, q += h w; accumulates the displacement since the step began.  The cap turns the
    first ``npv`` bodies about a joint's anchor (constraints/joints/pivot.py)."""
    for i in range(n):
        if B.kind[i] == STATIC or B.awake[i] == 0:
            continue
        w = B.w[i]
        if abs(w * h) > MAX_ROTATION:
            vx, vy, w = cap_about_pivot(PV, npv, i, B.q[i], B.v[i, 0], B.v[i, 1], w, B.inv_m[i], B.inv_i[i], h)
            B.v[i, 0] = vx
            B.v[i, 1] = vy
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


@kernel
def reset_displacements(n, DP, DQ, DC, DS):
    for i in range(n):
        DP[i, 0] = 0.0
        DP[i, 1] = 0.0
        DQ[i] = 0.0
        DC[i] = 1.0
        DS[i] = 0.0
