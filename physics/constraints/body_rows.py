"""The bodies as the constraint rows see them: one compact row per body.

The contact passes read and write, per body, the velocity (v, w), the inverse
mass and inertia and the displacement since the step began (dp and the
rotation as cos, sin).  In the body table these live in nine arrays; gathered
once per step into one (n, NB) array they are one cache line per body and one
base pointer in the loop.  Positions stay in the body table (the passes never
read them); velocities go back at the end of the step, and around the spring
solver, which works on the body table.
"""
from __future__ import annotations

import math

from numba import prange

from .._jit import kernel
from ..store import DYNAMIC, STATIC
from ..store.slot_list import at
from ..threads import MIN_BODIES, share
from .rotation_cap import MAX_ROTATION, cap_about_pivot

VX, VY, W, IM, II, DPX, DPY, DCOS, DSIN = range(9)
NB = 9
SMALL_ROTATION = 0.05  # below this (rad per sub-step) sin/cos of the increment by series


@kernel(forceinline=True)
def _gather(B, i, SB):
    SB[i, VX] = B.v[i, 0]
    SB[i, VY] = B.v[i, 1]
    SB[i, W] = B.w[i]
    SB[i, IM] = B.inv_m[i]
    SB[i, II] = B.inv_i[i]
    SB[i, DPX] = 0.0
    SB[i, DPY] = 0.0
    SB[i, DCOS] = 1.0
    SB[i, DSIN] = 0.0


@kernel
def gather_all(B, n, SB):
    """SB[:n] from the body table; no displacement yet."""
    for i in range(n):
        _gather(B, i, SB)


@kernel
def gather_bodies(B, idx, m, SB):
    """SB's rows of the ``m`` bodies listed in ``idx`` (store/slot_list.py), as ``gather_all``."""
    for k in range(m):
        _gather(B, at(idx, k), SB)


@kernel
def store_velocities(B, idx, m, SB):
    for k in range(m):
        i = at(idx, k)
        B.v[i, 0] = SB[i, VX]
        B.v[i, 1] = SB[i, VY]
        B.w[i] = SB[i, W]


@kernel
def load_velocities(B, idx, m, SB):
    for k in range(m):
        i = at(idx, k)
        SB[i, VX] = B.v[i, 0]
        SB[i, VY] = B.v[i, 1]
        SB[i, W] = B.w[i]


@kernel
def integrate_row_velocities(B, idx, m, SB, gx, gy, h, nthr):
    """Gravity and user forces on the awake dynamic bodies among the ``m`` listed in ``idx``
    (store/slot_list.py), into the rows' velocities; split between ``nthr`` threads for many
    bodies (each body on its own: the same numbers for any split; None: the serial build,
    physics/threads.py)."""
    if nthr is not None:
        if nthr > 1 and m >= MIN_BODIES * nthr:
            _velocities_split(B, idx, m, SB, gx, gy, h, nthr)
            return
    _velocities(B, idx, 0, m, SB, gx, gy, h)


@kernel(parallel=True)
def _velocities_split(B, idx, m, SB, gx, gy, h, nthr):
    for t in prange(nthr):
        lo, hi = share(m, t, nthr)
        _velocities(B, idx, lo, hi, SB, gx, gy, h)


@kernel
def _velocities(B, idx, k0, k1, SB, gx, gy, h):
    for k in range(k0, k1):
        i = at(idx, k)
        if B.kind[i] != DYNAMIC or B.awake[i] == 0:
            continue
        SB[i, VX] += h * (gx + B.inv_m[i] * B.f[i, 0])
        SB[i, VY] += h * (gy + B.inv_m[i] * B.f[i, 1])
        SB[i, W] += h * B.inv_i[i] * B.tau[i]


@kernel
def integrate_row_positions(B, idx, m, SB, h, PV, npv, nthr):
    """_positions over the ``m`` bodies listed in ``idx``, split between ``nthr`` threads as
    integrate_row_velocities."""
    if nthr is not None:
        if nthr > 1 and m >= MIN_BODIES * nthr:
            _positions_split(B, idx, m, SB, h, PV, npv, nthr)
            return
    _positions(B, idx, 0, m, SB, h, PV, npv)


@kernel(parallel=True)
def _positions_split(B, idx, m, SB, h, PV, npv, nthr):
    for t in prange(nthr):
        lo, hi = share(m, t, nthr)
        _positions(B, idx, lo, hi, SB, h, PV, npv)


@kernel
def _positions(B, idx, k0, k1, SB, h, PV, npv):
    """x += h v, q += h w with the rows' velocities (rotation per sub-step capped at
    MAX_ROTATION, about a joint's anchor for the first ``npv`` bodies: joints/pivot.py);
    accumulates the displacement since the step began.

    B.q advances by exactly h w; the displacement's (cos, sin) is composed with
    the increment's rotation, whose sin and cos for |h w| < SMALL_ROTATION come
    from their series to within rounding (first omitted terms < 1e-15) instead
    of two libm calls per body and sub-step.
    """
    for k in range(k0, k1):
        i = at(idx, k)
        if B.kind[i] == STATIC or B.awake[i] == 0:
            continue
        w = SB[i, W]
        if abs(w * h) > MAX_ROTATION:
            vx, vy, w = cap_about_pivot(PV, npv, i, B.q[i], SB[i, VX], SB[i, VY], w, SB[i, IM], SB[i, II], h)
            SB[i, VX] = vx
            SB[i, VY] = vy
            SB[i, W] = w
        dx = h * SB[i, VX]
        dy = h * SB[i, VY]
        B.x[i, 0] += dx
        B.x[i, 1] += dy
        t = h * w
        B.q[i] += t
        SB[i, DPX] += dx
        SB[i, DPY] += dy
        if t == 0.0:
            continue
        if abs(t) < SMALL_ROTATION:
            t2 = t * t
            c = 1.0 - t2 * (0.5 - t2 * (1.0 / 24.0 - t2 * (1.0 / 720.0)))
            s = t * (1.0 - t2 * (1.0 / 6.0 - t2 * (1.0 / 120.0 - t2 * (1.0 / 5040.0))))
        else:
            c = math.cos(t)
            s = math.sin(t)
        c0 = SB[i, DCOS]
        s0 = SB[i, DSIN]
        SB[i, DCOS] = c0 * c - s0 * s
        SB[i, DSIN] = s0 * c + c0 * s
