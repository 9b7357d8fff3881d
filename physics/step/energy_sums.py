"""The energy guard's sums, computed inside the step's opening and closing kernels.

The guard (energy_guard.py) needs, before and after every step, the world's kinetic,
gravitational and elastic energy, the dynamic mass (its noise floor) and whether anything
supplies energy from outside (a user force, a moving kinematic body).  As numpy over the body
table that was ~0.1 ms a step on pyramid20 (issue 17): about 25 array operations, each paying
its call cost.  These loops run inside begin_step / end_step (frame.py), over the bodies those
visit (the moving ones in the one-call step, step/active.py, with the sleeping ones' sums kept
while they sleep), so the guard costs a few arithmetic operations per body and no extra call.
"""
from __future__ import annotations

from .._jit import kernel
from ..store import DYNAMIC, KINEMATIC
from ..store.flat import bodies_view, joints_view
from ..store.joints import ANGULAR_MOTOR, BROKEN, MOTOR, MOUSE
from ..store.slot_list import at
from .checkpoint import spring_energy

#: the slots of the sums array: kinetic, gravitational, elastic energy (J), dynamic mass (kg),
#: external input (1.0 or 0.0), push-out allowance (J, after the step only: push_out.py), and the lowest
#: gravitational potential of a dynamic body (J/kg: min over i of -g . x_i)
KE, PE, ELASTIC, MASS, EXTERNAL, PUSH, LOWEST = range(7)
SUMS = 7


@kernel(forceinline=True)
def _input(B, i):
    """Body i takes energy from outside: a user force or torque, or it is a moving kinematic
    body ("!= 0.0" is true for NaN too: a non-finite force is an input, refused later)."""
    if B.f[i, 0] != 0.0 or B.f[i, 1] != 0.0 or B.tau[i] != 0.0:
        return True
    return B.kind[i] == KINEMATIC and (B.v[i, 0] != 0.0 or B.v[i, 1] != 0.0 or B.w[i] != 0.0)


@kernel(forceinline=True)
def _body_sums(B, idx, m, gx, gy):
    """(KE, PE, MASS, LOWEST, EXTERNAL) of the ``m`` bodies listed in ``idx``."""
    ke = 0.0
    pe = 0.0
    mass = 0.0
    ext = 0.0
    lowest = 0.0
    for k in range(m):
        i = at(idx, k)
        if B.kind[i] == DYNAMIC:
            vx = B.v[i, 0]
            vy = B.v[i, 1]
            w = B.w[i]
            mi = B.m[i]
            ke += 0.5 * (mi * (vx * vx + vy * vy) + B.inertia[i] * w * w)
            u = -(B.x[i, 0] * gx + B.x[i, 1] * gy)
            pe += mi * u
            lowest = u if mass == 0.0 else min(lowest, u)
            mass += mi
        if _input(B, i):
            ext = 1.0
    return ke, pe, mass, lowest, ext


@kernel
def rest_sums(B, idx, m, gx, gy, out):
    """The sums of the ``m`` bodies listed in ``idx`` (store/slot_list.py) that are at rest
    (sleeping) into ``out``: the part of ``guard_sums`` that stays the same while they sleep
    (step/active.py keeps it)."""
    ke, pe, mass, lowest, ext = _body_sums(B, idx, m, gx, gy)
    for j in range(SUMS):
        out[j] = 0.0
    out[KE] = ke
    out[PE] = pe
    out[MASS] = mass
    out[LOWEST] = lowest
    out[EXTERNAL] = ext


@kernel
def guard_sums(B, S, idx, m, ns, gx, gy, rest, out):
    """Fill ``out[KE..EXTERNAL]`` and ``out[LOWEST]`` from the ``m`` bodies listed in ``idx``
    (store/slot_list.py), the sums ``rest`` of the others (``rest_sums``; zeros when every body
    is listed) and the ``ns`` springs."""
    ke, pe, mass, lowest, ext = _body_sums(B, idx, m, gx, gy)
    if rest[MASS] > 0.0:
        lowest = rest[LOWEST] if mass == 0.0 else min(lowest, rest[LOWEST])
        mass += rest[MASS]
    elastic = 0.0
    for s in range(ns):
        elastic += spring_energy(B, S, s)
    out[KE] = ke + rest[KE]
    out[PE] = pe + rest[PE]
    out[ELASTIC] = elastic
    out[MASS] = mass
    out[EXTERNAL] = max(ext, rest[EXTERNAL])
    out[LOWEST] = lowest


@kernel(entry=True, runtime=True)
def motor_power(JF, JI, BF, BI, nj):
    """``motor_power_of`` over the joint and body tables' flat arrays."""
    return motor_power_of(joints_view(JF, JI), bodies_view(BF, BI), nj)


@kernel
def motor_power_of(J, B, nj):
    """(P, dragged): P bounds the power (W) the ``nj`` joints' motors can put in at the bodies'
    current velocities, and ``dragged`` says a mouse joint pulls (the user's input, unbounded).

    A motor's power is its force or torque times the relative speed it acts on, so a motor of
    at most T N m on a relative angular velocity w_rel supplies at most T |w_rel|; a force of at
    most F at the anchors supplies at most F |v_rel|, and the anchors' relative velocity is at
    most |v_b - v_a| + |w_a| |r_a| + |w_b| |r_b| (r: the anchor arms).  A motor used as joint
    friction (speed 0) only takes energy out; the bound still allows it T |w_rel|."""
    p = 0.0
    dragged = False
    for j in range(nj):
        if J.flags[j] & BROKEN or (J.max_motor[j] <= 0.0 and not (J.kind[j] == MOTOR and J.max_torque[j] > 0.0)):
            continue
        k = J.kind[j]
        if k == MOUSE:
            dragged = True
            continue
        a, b = J.a[j], J.b[j]
        wa = B.w[a]
        wb = B.w[b] if b >= 0 else 0.0
        w_rel = abs(wb - wa)
        if ANGULAR_MOTOR[k]:
            p += J.max_motor[j] * w_rel
            continue
        dvx = (B.v[b, 0] if b >= 0 else 0.0) - B.v[a, 0]
        dvy = (B.v[b, 1] if b >= 0 else 0.0) - B.v[a, 1]
        ra = (J.la[j, 0] ** 2 + J.la[j, 1] ** 2) ** 0.5
        rb = (J.lb[j, 0] ** 2 + J.lb[j, 1] ** 2) ** 0.5 if b >= 0 else 0.0
        v_rel = (dvx * dvx + dvy * dvy) ** 0.5 + abs(wa) * ra + abs(wb) * rb
        p += J.max_motor[j] * v_rel
        if k == MOTOR:
            p += J.max_torque[j] * w_rel
    return p, dragged
