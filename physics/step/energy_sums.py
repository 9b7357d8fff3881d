"""The energy guard's sums, computed inside the step's opening and closing kernels.

The guard (energy_guard.py) needs, before and after every step, the world's kinetic,
gravitational and elastic energy, the dynamic mass (its noise floor) and whether anything
supplies energy from outside (a user force, a moving kinematic body).  As numpy over the body
table that was ~0.1 ms a step on pyramid20 (issue 17): about 25 array operations, each paying
its call cost.  These loops run inside begin_step / end_step (frame.py), which already visit
every body, so the guard costs a few arithmetic operations per body and no extra call.
"""
from __future__ import annotations

from .._jit import kernel
from ..store import DYNAMIC, KINEMATIC
from ..store.flat import joints_view
from ..store.joints import BROKEN, MOTOR
from .checkpoint import spring_energy

#: the slots of the sums array: kinetic, gravitational, elastic energy (J), dynamic mass (kg),
#: external input (1.0 or 0.0), push-out allowance (J, after the step only)
KE, PE, ELASTIC, MASS, EXTERNAL, PUSH = range(6)
SUMS = 6


@kernel(_nrt=False)
def guard_sums(B, S, n, ns, gx, gy, out):
    """Fill ``out[KE..EXTERNAL]`` from the first ``n`` bodies and ``ns`` springs."""
    ke = 0.0
    pe = 0.0
    mass = 0.0
    ext = 0.0
    for i in range(n):
        kind = B.kind[i]
        vx = B.v[i, 0]
        vy = B.v[i, 1]
        w = B.w[i]
        if kind == DYNAMIC:
            m = B.m[i]
            ke += 0.5 * (m * (vx * vx + vy * vy) + B.inertia[i] * w * w)
            pe -= m * (B.x[i, 0] * gx + B.x[i, 1] * gy)
            mass += m
        elif kind == KINEMATIC and (vx != 0.0 or vy != 0.0 or w != 0.0):
            ext = 1.0
        # "!= 0.0" is true for NaN too: a non-finite force is an input (and is refused later)
        if B.f[i, 0] != 0.0 or B.f[i, 1] != 0.0 or B.tau[i] != 0.0:
            ext = 1.0
    elastic = 0.0
    for s in range(ns):
        elastic += spring_energy(B, S, s)
    out[KE] = ke
    out[PE] = pe
    out[ELASTIC] = elastic
    out[MASS] = mass
    out[EXTERNAL] = ext


@kernel(_nrt=False)
def push_sum(B, n, Ca, Cb, nc, count, speed):
    """1/2 sum_i m_i (c_i speed)^2 over the dynamic bodies, c_i body i's contact manifolds
    (``count``: int scratch of at least n)."""
    for i in range(n):
        count[i] = 0
    for k in range(nc):
        count[Ca[k]] += 1
        count[Cb[k]] += 1
    total = 0.0
    for i in range(n):
        if B.kind[i] == DYNAMIC and count[i] > 0:
            v = count[i] * speed
            total += 0.5 * B.m[i] * v * v
    return total


@kernel
def joints_working(JF, JI, nj):
    """A motor or mouse joint that can supply energy (a positive motor force or torque, or a motor
    joint's torque limit) and is not broken, among the ``nj`` joints."""
    J = joints_view(JF, JI)
    for j in range(nj):
        if J.flags[j] & BROKEN:
            continue
        if J.max_motor[j] > 0.0 or (J.kind[j] == MOTOR and J.max_torque[j] > 0.0):
            return True
    return False
