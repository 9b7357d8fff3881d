"""Prototype of a step that is one compiled call over flat data (measured, not the engine).

All float state of a world lives in one float64 buffer and all integer state in one int64 buffer;
``L`` (int64) holds each table's offset, capacity and row count.  The driver rebuilds each table
as a 2-D view of its buffer (named column constants below) and runs the stages in order, so a
Python ``step()`` is one call with four arrays, whatever the scene holds.

This prototype solves what the small-scene targets need to be measured: sub-stepped soft
revolute joints (Box2D v3's soft step: integrate velocities, warm start, biased solve, integrate
positions, relax) on discs, for the pendulum.  ``python -m bench.prototypes.flat_step`` prints
the call overhead, our us/step against pymunk's, measured interleaved, and the cold compile.
"""
from __future__ import annotations

import math
import time

import numpy as np
from numba import njit

# -- layout: table slots in L (offset into its buffer, capacity, rows in use, columns) --------
BODIES_F, BODIES_I, JOINTS_F, JOINTS_I = 0, 1, 2, 3
L_FIELDS = 4  # per table: offset, capacity, n, columns

# body float columns
X, Y, Q, VX, VY, W, IM, II, DX, DY, DQ = range(11)
NBF = 11
# body int columns
KIND, AWAKE = range(2)
NBI = 2
DYNAMIC, STATIC = 0, 1
# revolute joint float columns: local anchors, world arms of this step, effective mass,
# accumulated impulse, separation at the step's start
LAX, LAY, LBX, LBY, RAX, RAY, RBX, RBY, K11, K12, K22, PX, PY, SX, SY = range(15)
NJF = 15
JA, JB = range(2)  # body slots (-1: the world)
NJI = 2
# context
C_DT, C_GX, C_GY, C_SUBSTEPS, C_HERTZ, C_ZETA = range(6)


@njit(cache=True)
def table(buf, L, t):
    o, cap, cols = L[t, 0], L[t, 1], L[t, 3]
    return buf[o:o + cap * cols].reshape((cap, cols))


@njit(cache=True)
def softness(hertz, zeta, h):
    """(bias rate, mass scale, impulse scale): Box2D v3's soft constraint coefficients."""
    if hertz == 0.0:
        return 0.0, 1.0, 0.0
    omega = 2.0 * math.pi * hertz
    a1 = 2.0 * zeta + h * omega
    a2 = h * omega * a1
    a3 = 1.0 / (1.0 + a2)
    return omega / a1, a2 * a3, a3


@njit(cache=True)
def integrate_velocities(B, BI, n, gx, gy, h):
    for i in range(n):
        if BI[i, KIND] != DYNAMIC:
            continue
        B[i, VX] += h * gx
        B[i, VY] += h * gy


@njit(cache=True)
def integrate_positions(B, BI, n, h):
    for i in range(n):
        if BI[i, KIND] != DYNAMIC:
            continue
        B[i, X] += h * B[i, VX]
        B[i, Y] += h * B[i, VY]
        B[i, Q] += h * B[i, W]
        B[i, DX] += h * B[i, VX]
        B[i, DY] += h * B[i, VY]
        B[i, DQ] += h * B[i, W]


@njit(cache=True)
def prepare_revolute(B, J, JI, nj):
    for k in range(nj):
        a, b = JI[k, JA], JI[k, JB]
        ca, sa = (math.cos(B[a, Q]), math.sin(B[a, Q])) if a >= 0 else (1.0, 0.0)
        cb, sb = (math.cos(B[b, Q]), math.sin(B[b, Q])) if b >= 0 else (1.0, 0.0)
        J[k, RAX] = ca * J[k, LAX] - sa * J[k, LAY]
        J[k, RAY] = sa * J[k, LAX] + ca * J[k, LAY]
        J[k, RBX] = cb * J[k, LBX] - sb * J[k, LBY]
        J[k, RBY] = sb * J[k, LBX] + cb * J[k, LBY]
        pa = (B[a, X], B[a, Y]) if a >= 0 else (0.0, 0.0)
        pb = (B[b, X], B[b, Y]) if b >= 0 else (0.0, 0.0)
        J[k, SX] = (pb[0] + J[k, RBX]) - (pa[0] + J[k, RAX])
        J[k, SY] = (pb[1] + J[k, RBY]) - (pa[1] + J[k, RAY])
        ma = B[a, IM] if a >= 0 else 0.0
        ia = B[a, II] if a >= 0 else 0.0
        mb = B[b, IM] if b >= 0 else 0.0
        ib = B[b, II] if b >= 0 else 0.0
        rax, ray, rbx, rby = J[k, RAX], J[k, RAY], J[k, RBX], J[k, RBY]
        J[k, K11] = ma + mb + ray * ray * ia + rby * rby * ib
        J[k, K12] = -ray * rax * ia - rby * rbx * ib
        J[k, K22] = ma + mb + rax * rax * ia + rbx * rbx * ib


@njit(cache=True)
def _apply(B, a, b, rax, ray, rbx, rby, px, py):
    if a >= 0:
        B[a, VX] -= B[a, IM] * px
        B[a, VY] -= B[a, IM] * py
        B[a, W] -= B[a, II] * (rax * py - ray * px)
    if b >= 0:
        B[b, VX] += B[b, IM] * px
        B[b, VY] += B[b, IM] * py
        B[b, W] += B[b, II] * (rbx * py - rby * px)


@njit(cache=True)
def _arms(B, J, k, a, b):
    """The arms rotated with their bodies since the step began."""
    dqa = B[a, DQ] if a >= 0 else 0.0
    dqb = B[b, DQ] if b >= 0 else 0.0
    ca, sa, cb, sb = math.cos(dqa), math.sin(dqa), math.cos(dqb), math.sin(dqb)
    return (ca * J[k, RAX] - sa * J[k, RAY], sa * J[k, RAX] + ca * J[k, RAY],
            cb * J[k, RBX] - sb * J[k, RBY], sb * J[k, RBX] + cb * J[k, RBY])


@njit(cache=True)
def warm_revolute(B, J, JI, nj):
    for k in range(nj):
        a, b = JI[k, JA], JI[k, JB]
        rax, ray, rbx, rby = _arms(B, J, k, a, b)
        _apply(B, a, b, rax, ray, rbx, rby, J[k, PX], J[k, PY])


@njit(cache=True)
def solve_revolute(B, J, JI, nj, bias_rate, mass_scale, impulse_scale, use_bias):
    """Box2D v3's soft point constraint (revolute_joint.c, the point part): the arms rotate with
    the bodies since the step began (dq), the separation is the step's start plus the motion."""
    for k in range(nj):
        a, b = JI[k, JA], JI[k, JB]
        rax, ray, rbx, rby = _arms(B, J, k, a, b)
        vax, vay, wa = (B[a, VX], B[a, VY], B[a, W]) if a >= 0 else (0.0, 0.0, 0.0)
        vbx, vby, wb = (B[b, VX], B[b, VY], B[b, W]) if b >= 0 else (0.0, 0.0, 0.0)
        cdx = vbx - wb * rby - (vax - wa * ray)
        cdy = vby + wb * rbx - (vay + wa * rax)
        bx = by = 0.0
        ms, isc = 1.0, 0.0
        if use_bias:
            dxa = B[a, DX] if a >= 0 else 0.0
            dya = B[a, DY] if a >= 0 else 0.0
            dxb = B[b, DX] if b >= 0 else 0.0
            dyb = B[b, DY] if b >= 0 else 0.0
            sx = J[k, SX] + (dxb - dxa) + (rbx - J[k, RBX]) - (rax - J[k, RAX])
            sy = J[k, SY] + (dyb - dya) + (rby - J[k, RBY]) - (ray - J[k, RAY])
            bx, by = bias_rate * sx, bias_rate * sy
            ms, isc = mass_scale, impulse_scale
        ma = B[a, IM] if a >= 0 else 0.0
        ia = B[a, II] if a >= 0 else 0.0
        mb = B[b, IM] if b >= 0 else 0.0
        ib = B[b, II] if b >= 0 else 0.0
        # K with the arms as they are now (the prepared one is the step's start)
        k11 = ma + mb + ray * ray * ia + rby * rby * ib
        k12 = -ray * rax * ia - rby * rbx * ib
        k22 = ma + mb + rax * rax * ia + rbx * rbx * ib
        det = k11 * k22 - k12 * k12
        inv = 1.0 / det if det != 0.0 else 0.0
        rx, ry = cdx + bx, cdy + by
        ix = -ms * inv * (k22 * rx - k12 * ry) - isc * J[k, PX]
        iy = -ms * inv * (k11 * ry - k12 * rx) - isc * J[k, PY]
        J[k, PX] += ix
        J[k, PY] += iy
        _apply(B, a, b, rax, ray, rbx, rby, ix, iy)


@njit(cache=True)
def step(FB, IB, L, ctx):
    """One step: the driver.  Stages are plain functions over the tables' views."""
    B = table(FB, L, BODIES_F)
    BI = table(IB, L, BODIES_I)
    J = table(FB, L, JOINTS_F)
    JI = table(IB, L, JOINTS_I)
    n, nj = L[BODIES_F, 2], L[JOINTS_F, 2]
    dt = ctx[C_DT]
    ns = int(ctx[C_SUBSTEPS])
    h = dt / ns
    bias, mscale, iscale = softness(min(ctx[C_HERTZ], 0.25 / h), ctx[C_ZETA], h)
    for i in range(n):
        B[i, DX] = 0.0
        B[i, DY] = 0.0
        B[i, DQ] = 0.0
    prepare_revolute(B, J, JI, nj)
    for _ in range(ns):
        integrate_velocities(B, BI, n, ctx[C_GX], ctx[C_GY], h)
        warm_revolute(B, J, JI, nj)
        solve_revolute(B, J, JI, nj, bias, mscale, iscale, True)
        integrate_positions(B, BI, n, h)
        solve_revolute(B, J, JI, nj, bias, mscale, iscale, False)


@njit(cache=True)
def noop(FB, IB, L, ctx):
    """The driver's signature and nothing else: the cost of the call itself."""
    return FB.shape[0]


class FlatWorld:
    """Just enough of a world to build the pendulum scenes and step them."""

    def __init__(self, nb_cap=8, nj_cap=8, dt=1 / 60, gravity=(0.0, -10.0), substeps=4):
        self.L = np.zeros((4, L_FIELDS), np.int64)
        caps = ((nb_cap, NBF), (nb_cap, NBI), (nj_cap, NJF), (nj_cap, NJI))
        fo = io = 0
        for t, (cap, cols) in enumerate(caps):
            isint = t in (BODIES_I, JOINTS_I)
            self.L[t] = (io if isint else fo, cap, 0, cols)
            if isint:
                io += cap * cols
            else:
                fo += cap * cols
        self.FB = np.zeros(fo)
        self.IB = np.zeros(io, np.int64)
        self.ctx = np.array([dt, gravity[0], gravity[1], substeps, 60.0, 1.0])
        self._args = (self.FB, self.IB, self.L, self.ctx)

    def view(self, t):
        o, cap, n, cols = self.L[t]
        return (self.IB if t in (BODIES_I, JOINTS_I) else self.FB)[o:o + cap * cols].reshape(cap, cols)

    def add_disc(self, x, y, r=0.25, density=1.0):
        i = self.L[BODIES_F, 2]
        m = density * math.pi * r * r
        B, BI = self.view(BODIES_F), self.view(BODIES_I)
        B[i, X], B[i, Y], B[i, IM], B[i, II] = x, y, 1 / m, 1 / (0.5 * m * r * r)
        BI[i, KIND] = DYNAMIC
        self.L[BODIES_F, 2] += 1
        self.L[BODIES_I, 2] += 1
        return i

    def add_revolute(self, a, b, anchor):
        k = self.L[JOINTS_F, 2]
        B, J, JI = self.view(BODIES_F), self.view(JOINTS_F), self.view(JOINTS_I)
        for col_x, col_y, body in ((LAX, LAY, a), (LBX, LBY, b)):
            px, py = (B[body, X], B[body, Y]) if body >= 0 else (0.0, 0.0)
            J[k, col_x], J[k, col_y] = anchor[0] - px, anchor[1] - py  # bodies start unrotated
        JI[k, JA], JI[k, JB] = a, b
        self.L[JOINTS_F, 2] += 1
        self.L[JOINTS_I, 2] += 1

    def step(self):
        step(*self._args)


def pendulum_flat():
    w = FlatWorld()
    d = w.add_disc(1.0, 0.0)
    w.add_revolute(-1, d, (0.0, 0.0))
    return w


def pendulum_pymunk():
    import pymunk
    s = pymunk.Space()
    s.gravity = (0, -10)
    body = pymunk.Body(0, 0)
    body.position = (1.0, 0.0)
    c = pymunk.Circle(body, 0.25)
    c.density = 1.0
    s.add(body, c)
    s.add(pymunk.PivotJoint(s.static_body, body, (0, 0)))
    return s


def _time(fn, n):
    t = time.perf_counter()
    for _ in range(n):
        fn()
    return (time.perf_counter() - t) / n * 1e6


def main():
    t0 = time.process_time()
    w = pendulum_flat()
    w.step()
    print(f"first step (compile or cache load): {time.process_time() - t0:.2f} CPU s")
    s = pendulum_pymunk()
    noop(*w._args)
    call = np.median([_time(lambda: noop(*w._args), 20000) for _ in range(5)])
    print(f"the call alone (four arrays): {call:.2f} us")
    rounds = []
    for _ in range(7):
        rounds.append((_time(w.step, 20000), _time(lambda: s.step(1 / 60), 20000)))
    ours, theirs = np.median(np.array(rounds), axis=0)
    print(f"pendulum: flat prototype {ours:.2f} us/step, pymunk {theirs:.2f} us/step, ratio {ours / theirs:.2f}")
    B = w.view(BODIES_F)
    print(f"after {7 * 20000 + 1} steps the disc is {math.hypot(B[0, X], B[0, Y]):.6f} m from the pivot (1.0)")


if __name__ == "__main__":
    main()
