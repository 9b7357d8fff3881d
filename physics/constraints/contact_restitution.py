"""Restitution of the soft contact rows (constraints/contact_soft.py): Newton's law at first touch.

Newton's impact law v_n' = -e v_n (seed eq. 13) needs the normal speed *at impact*.  Box2D v3
(contact_solver.c, b2ApplyRestitution) reflects the speed before the step's solve, once, after
the last sub-step.  Two things make that bounce low (issue 18: a 1 m drop at e = 0.5 rises
0.175 m, not 0.25 m):

* the body falls on during the step before it touches, so the speed at touch is higher than
  the speed when the step began: here ``VN0`` is the point's normal speed in the sub-step in
  which it first pushed (after that sub-step's gravity; recorded by the biased pass);
* the body rests on the ground from the touch to the end of the step, and the height it would
  have risen in that time is lost: here the pass runs after every sub-step, on the points that
  pushed for the first time in it, so at most one sub-step is lost, not one step;
* friction acts while a body is being stopped, and the stop of a turned box's face (its two
  points at different gaps) turns it, so friction leaves it sliding along the wall; reflecting
  the full normal speed then adds energy.  With e <= 1 a bounce never leaves the pair with
  more kinetic energy than it had at first touch (``KE0``): the impulses are scaled down to
  meet that cap (Stronge's energetic restitution, "Impact Mechanics", 2000, as a bound);
* the two points of a face hit together, but one Gauss-Seidel pass over them (Box2D's) pushes
  the first, turns the body, and the second then undoes part of the first: the face's centre
  leaves slower than -e v_n.  Two points are solved together as a 2x2 LCP (constraints/block.py)
  with the target speeds -e v_n0 of both.

A point bounces once per step, only if it hit faster than ``p.restitution_threshold`` and pushed
(a speculative point never reached does not bounce).  Bodies bouncing together in one sub-step
(a body squeezed between two others) are capped together (restitution_cluster.py).
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel
from .block import solve_block
from .body_rows import II, IM, VX, VY, W
from .contact_soft import BLOCK, BOUNCED, INV_DET, JN, K11, K12, K22, KE0, MASS_N, MAXJ, NX, NY, PT, RNA, RNB, VN0
from .restitution_chain import chain_impacts
from .restitution_cluster import cap_clusters, save_velocities


@kernel(runtime=True)
def restitution_contacts(c, p, SB, C, R, V0):
    """Bounce the points that first pushed since the last call (see the module doc), then cap
    each cluster of bodies bouncing together at its energy at the sub-step start ``V0``
    (restitution_cluster.py)."""
    threshold = p.restitution_threshold
    nc = c.nc
    due = np.zeros(nc, dtype=np.bool_)
    some = False
    for k in range(nc):
        if C.e[k] != 0.0 and (_due(R, k, 0, threshold) or (C.count[k] == 2 and _due(R, k, PT, threshold))):
            due[k] = True
            some = True
    if not some:
        return
    n = c.n
    VR = np.empty((n, 3))
    save_velocities(SB, n, VR)
    J0 = np.empty((nc, 2))
    for k in range(nc):
        J0[k, 0] = R[k, JN]
        J0[k, 1] = R[k, PT + JN]
    rows = chain_impacts(c, p, SB, C, R, due)  # rows of touching bodies struck (restitution_chain.py)
    for k in range(nc):
        if due[k] and not rows[k]:
            _restitution(SB, C, k, R, threshold, C.e[k])
        due[k] = due[k] or rows[k]
    cap_clusters(SB, C, nc, n, R, due, V0, VR, J0)


@kernel(forceinline=True)
def _due(R, k, o, threshold):
    return R[k, o + BOUNCED] == 0.0 and R[k, o + MAXJ] > 0.0 and R[k, o + VN0] < -threshold


@kernel
def _apply(SB, a, b, nx, ny, j0, rna0, rnb0, j1, rna1, rnb1, ke0, e):
    """Normal impulses j0, j1 at two points (anchor projections r x n of a and b), scaled by the
    largest factor <= 1 that keeps the pair's kinetic energy at most ``ke0`` when e <= 1."""
    ima = SB[a, IM]
    imb = SB[b, IM]
    iia = SB[a, II]
    iib = SB[b, II]
    j = j0 + j1
    # velocity changes per unit scale
    dax = -ima * j * nx
    day = -ima * j * ny
    dwa = -iia * (j0 * rna0 + j1 * rna1)
    dbx = imb * j * nx
    dby = imb * j * ny
    dwb = iib * (j0 * rnb0 + j1 * rnb1)
    s = 1.0
    if e <= 1.0:
        # E(s) = E0 + s lin + s^2 quad (impulses along n: quad > 0 unless nothing moves)
        e0 = 0.0
        lin = 0.0
        quad = 0.0
        for i, dx, dy, dw in ((a, dax, day, dwa), (b, dbx, dby, dwb)):
            im = SB[i, IM]
            ii = SB[i, II]
            if im > 0.0:
                e0 += 0.5 * (SB[i, VX] ** 2 + SB[i, VY] ** 2) / im
                lin += (SB[i, VX] * dx + SB[i, VY] * dy) / im
                quad += 0.5 * (dx * dx + dy * dy) / im
            if ii > 0.0:
                e0 += 0.5 * SB[i, W] ** 2 / ii
                lin += SB[i, W] * dw / ii
                quad += 0.5 * dw * dw / ii
        if quad > 0.0 and e0 + lin + quad > ke0:
            disc = lin * lin - 4.0 * quad * (e0 - ke0)
            s = max(0.0, (-lin + math.sqrt(disc)) / (2.0 * quad)) if disc > 0.0 else 0.0
            s = min(s, 1.0)
    SB[a, VX] += s * dax
    SB[a, VY] += s * day
    SB[a, W] += s * dwa
    SB[b, VX] += s * dbx
    SB[b, VY] += s * dby
    SB[b, W] += s * dwb
    return s


@kernel
def _speed(SB, a, b, nx, ny, rna, rnb):
    return (SB[b, VX] - SB[a, VX]) * nx + (SB[b, VY] - SB[a, VY]) * ny + SB[b, W] * rnb - SB[a, W] * rna


@kernel
def _restitution(SB, C, k, R, threshold, e):
    a = C.a[k]
    b = C.b[k]
    nx = R[k, NX]
    ny = R[k, NY]
    cnt = C.count[k]
    due0 = _due(R, k, 0, threshold)
    due1 = cnt == 2 and _due(R, k, PT, threshold)
    if due0 and due1 and R[k, BLOCK] != 0.0:
        old0 = R[k, JN]
        old1 = R[k, PT + JN]
        k11 = R[k, K11]
        k12 = R[k, K12]
        k22 = R[k, K22]
        v0 = _speed(SB, a, b, nx, ny, R[k, RNA], R[k, RNB])
        v1 = _speed(SB, a, b, nx, ny, R[k, PT + RNA], R[k, PT + RNB])
        # free speeds (this manifold's impulses removed) minus the targets -e v_n0
        g0 = v0 - (k11 * old0 + k12 * old1) + e * R[k, VN0]
        g1 = v1 - (k12 * old0 + k22 * old1) + e * R[k, PT + VN0]
        ok, x0, x1 = solve_block(k11, k12, k22, R[k, INV_DET], R[k, MASS_N], R[k, PT + MASS_N], g0, g1, 1.0)
        if ok:
            sc = _apply(SB, a, b, nx, ny, x0 - old0, R[k, RNA], R[k, RNB], x1 - old1, R[k, PT + RNA], R[k, PT + RNB],
                        R[k, KE0], e)
            R[k, JN] = old0 + sc * (x0 - old0)
            R[k, PT + JN] = old1 + sc * (x1 - old1)
            R[k, BOUNCED] = 1.0
            R[k, PT + BOUNCED] = 1.0
            return
    for q in range(cnt):
        o = q * PT
        if not _due(R, k, o, threshold):
            continue
        rna = R[k, o + RNA]
        rnb = R[k, o + RNB]
        vn = _speed(SB, a, b, nx, ny, rna, rnb)
        old = R[k, o + JN]
        new = max(old - R[k, o + MASS_N] * (vn + e * R[k, o + VN0]), 0.0)
        sc = _apply(SB, a, b, nx, ny, new - old, rna, rnb, 0.0, 0.0, 0.0, R[k, KE0], e)
        R[k, o + JN] = old + sc * (new - old)
        R[k, o + BOUNCED] = 1.0

