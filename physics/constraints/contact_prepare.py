"""A step's manifolds prepared straight into the wide blocks (constraints/contact_wide.py).

What ``contact_soft.prepare_contacts`` then ``contact_wide.pack`` leave in the blocks, without
the rows between, in two loops per run of blocks.  The first (``_stage``) reads each slot's
manifold and bodies (scattered reads, one slot after another) into a float64 staging area laid
out as the blocks, ``T[(b * NT + f) * LANES + l]``; the second (``_lanes``) computes the terms of
the eight lanes of a block side by side from it, a straight-line loop LLVM turns into vector
code, as the passes' (contact_coloured.py).  Its helpers take plain numbers and divide with
numpy's error model (a division by zero yields inf, not an exception branch, so that nothing
stops the vectoriser; none divides by zero here: each division is taken only where its divisor
is positive).  The terms and their order of operations are those of contact_soft.py's helpers,
so the blocks hold the same bits as the rows path.

The staging area is the tail of ``WV``, after the lanes' velocities (ColouredScratch sizes it):
``T = WV[capacity_blocks * V_SIZE:]``.  A padding lane (``order`` -1) stages zeros and gets the
terms of zeros, which no pass reads.
"""
from __future__ import annotations

import math

from numba import prange

from .._jit import kernel, kernel_noalias
from ..threads import MIN_SLOTS, share
from .body_rows import NB
from .colouring import LANES
from .contact_soft import DEEP, manifold_state, point_terms, prepared_block
from .contact_stiffness import contact_hertz, moving_size
from .contact_wide import (BLOCK_SIZE, PW, V_SIZE, W_BLOCK, W_BOUNCY, W_DEEP, W_INVDET, W_ISC, W_JN, W_JT, W_K11,
                           W_K12, W_K22, W_KE0, W_MAXJ, W_MN, W_MSC, W_MT, W_MU, W_NX, W_NY, W_RATE, W_RNA, W_RNB,
                           W_RTA, W_RTB, W_SEP, W_VN0)
from .softness import softness

L = LANES
P1 = PW * L  # offset of the second point's fields in a block
# a slot's staged inputs: the manifold state, the bodies' positions and bounding radii, both
# points and depths, the impulses, the friction pair, whether it has two points, its load
(T_NX, T_NY, T_IMA, T_IMB, T_IIA, T_IIB, T_WA, T_WB, T_DVN, T_DVT, T_XA, T_YA, T_XB, T_YB, T_P0X, T_P0Y, T_D0,
 T_P1X, T_P1Y, T_D1, T_JN0, T_JT0, T_JN1, T_JT1, T_MUS, T_MUD, T_TWO, T_LOAD, T_RA, T_RB) = range(30)
NT = 30
T_SIZE = NT * L  # staged floats per block


@kernel
def prepare_wide(ctx, par, B, C, order, slots, W, WV, GA, GB, nthr):
    """W, GA, GB for the slots 0..slots-1 (whole blocks) from the manifolds and the bodies at the
    start of the step (the module doc); split between ``nthr`` threads for many slots, in whole
    blocks (each slot on its own: the same numbers; None: the serial build, physics/threads.py)."""
    T = WV[GA.shape[0] // L * V_SIZE:]
    if nthr is not None:
        if nthr > 1 and slots >= MIN_SLOTS * nthr:
            _prepare_split(ctx, par, B, C, order, slots, W, T, GA, GB, nthr)
            return
    _prepare(ctx[0], par[0], B, C, order, 0, slots // L, W, T, GA, GB)


@kernel(parallel=True)
def _prepare_split(ctx, par, B, C, order, slots, W, T, GA, GB, nthr):
    """prepare_wide's blocks in one run per thread (the context and the parameters come as their
    one-element arrays: numba hands no record to a parallel loop)."""
    nb = slots // L
    for t in prange(nthr):
        lo, hi = share(nb, t, nthr)
        _prepare(ctx[0], par[0], B, C, order, lo, hi, W, T, GA, GB)


@kernel
def _prepare(c, p, B, C, order, b0, b1, W, T, GA, GB):
    """Blocks b0..b1-1: staged, then computed lane by lane side by side."""
    _stage(B, C, order, b0 * L, b1 * L, GA, GB, T)
    _lanes(b1 - b0, W[b0 * BLOCK_SIZE:b1 * BLOCK_SIZE], T[b0 * T_SIZE:b1 * T_SIZE], p.stick_speed, p.block_solver,
           p.hertz_static, p.hertz_dyn, p.damping_ratio, p.h, math.hypot(c.gx, c.gy))


@kernel
def _stage(B, C, order, j0, j1, GA, GB, T):
    """The inputs of slots j0..j1-1 into T, and their bodies' row offsets into GA, GB."""
    for j in range(j0, j1):
        k = order[j]
        t = j // L * T_SIZE + j % L
        if k < 0:  # padding
            for f in range(NT):
                T[t + f * L] = 0.0
            continue
        a, b, nx, ny, ima, imb, iia, iib, wa, wb, dvnx, dvtx = manifold_state(B, C, k)
        GA[j] = a * NB
        GB[j] = b * NB
        cnt = C.count[k]
        load = 0.0  # the points' impulses in point order, as contact_soft.prepared_softness sums them
        for q in range(cnt):
            load += C.jn[k, q]
        T[t + T_NX * L] = nx
        T[t + T_NY * L] = ny
        T[t + T_IMA * L] = ima
        T[t + T_IMB * L] = imb
        T[t + T_IIA * L] = iia
        T[t + T_IIB * L] = iib
        T[t + T_WA * L] = wa
        T[t + T_WB * L] = wb
        T[t + T_DVN * L] = dvnx
        T[t + T_DVT * L] = dvtx
        T[t + T_XA * L] = B.x[a, 0]
        T[t + T_YA * L] = B.x[a, 1]
        T[t + T_XB * L] = B.x[b, 0]
        T[t + T_YB * L] = B.x[b, 1]
        T[t + T_P0X * L] = C.point[k, 0, 0]
        T[t + T_P0Y * L] = C.point[k, 0, 1]
        T[t + T_D0 * L] = C.depth[k, 0]
        T[t + T_P1X * L] = C.point[k, 1, 0]
        T[t + T_P1Y * L] = C.point[k, 1, 1]
        T[t + T_D1 * L] = C.depth[k, 1]
        T[t + T_JN0 * L] = C.jn[k, 0]
        T[t + T_JT0 * L] = C.jt[k, 0]
        T[t + T_JN1 * L] = C.jn[k, 1]
        T[t + T_JT1 * L] = C.jt[k, 1]
        T[t + T_MUS * L] = C.mu_s[k]
        T[t + T_MUD * L] = C.mu_d[k]
        T[t + T_TWO * L] = 1.0 if cnt == 2 else 0.0
        T[t + T_LOAD * L] = load
        T[t + T_RA * L] = B.bound_r[a]
        T[t + T_RB * L] = B.bound_r[b]


@kernel_noalias(error_model="numpy")
def _lanes(nb, W_, T, stick, block_solver, hz_static, hz_dyn, zeta, h, g):
    """The blocks' fields from the staged inputs, the lanes side by side.  Both points' terms are
    computed and a one-point manifold's second point selected to zeros, as every choice here is a
    select: a branch on the data would stop LLVM from vectorising the loop."""
    for blk in range(nb):
        for l in range(L):
            i = blk * BLOCK_SIZE + l
            s = blk * T_SIZE + l
            nx = T[s + T_NX * L]
            ny = T[s + T_NY * L]
            ima = T[s + T_IMA * L]
            imb = T[s + T_IMB * L]
            iia = T[s + T_IIA * L]
            iib = T[s + T_IIB * L]
            wa = T[s + T_WA * L]
            wb = T[s + T_WB * L]
            dvn = T[s + T_DVN * L]
            dvt = T[s + T_DVT * L]
            xa = T[s + T_XA * L]
            ya = T[s + T_YA * L]
            xb = T[s + T_XB * L]
            yb = T[s + T_YB * L]
            mus = T[s + T_MUS * L]
            mud = T[s + T_MUD * L]
            two = T[s + T_TWO * L] != 0.0
            rna0, rnb0, rta0, rtb0, mn0, mt0, sep0, vn0, mu0 = point_terms(
                T[s + T_P0X * L], T[s + T_P0Y * L], T[s + T_D0 * L], mus, mud, xa, ya, xb, yb, nx, ny, ima, imb, iia,
                iib, dvn, dvt, wa, wb, stick)
            rna1, rnb1, rta1, rtb1, mn1, mt1, sep1, vn1, mu1 = point_terms(
                T[s + T_P1X * L], T[s + T_P1Y * L], T[s + T_D1 * L], mus, mud, xa, ya, xb, yb, nx, ny, ima, imb, iia,
                iib, dvn, dvt, wa, wb, stick)
            # the points' fields (written out: an array handed to an inlined helper may keep LLVM
            # from vectorising the loop); a one-point manifold's second point all zeros
            W_[i + W_RNA * L] = rna0
            W_[i + W_RNB * L] = rnb0
            W_[i + W_RTA * L] = rta0
            W_[i + W_RTB * L] = rtb0
            W_[i + W_MN * L] = mn0
            W_[i + W_MT * L] = mt0
            W_[i + W_SEP * L] = sep0
            W_[i + W_MU * L] = mu0
            W_[i + W_VN0 * L] = vn0
            W_[i + W_MAXJ * L] = 0.0
            W_[i + W_JN * L] = T[s + T_JN0 * L]
            W_[i + W_JT * L] = T[s + T_JT0 * L]
            W_[i + P1 + W_RNA * L] = rna1 if two else 0.0
            W_[i + P1 + W_RNB * L] = rnb1 if two else 0.0
            W_[i + P1 + W_RTA * L] = rta1 if two else 0.0
            W_[i + P1 + W_RTB * L] = rtb1 if two else 0.0
            W_[i + P1 + W_MN * L] = mn1 if two else 0.0
            W_[i + P1 + W_MT * L] = mt1 if two else 0.0
            W_[i + P1 + W_SEP * L] = sep1 if two else 0.0
            W_[i + P1 + W_MU * L] = mu1 if two else 0.0
            W_[i + P1 + W_VN0 * L] = vn1 if two else 0.0
            W_[i + P1 + W_MAXJ * L] = 0.0
            W_[i + P1 + W_JN * L] = T[s + T_JN1 * L] if two else 0.0
            W_[i + P1 + W_JT * L] = T[s + T_JT1 * L] if two else 0.0
            k11, k22, k12, ok, inv_det = prepared_block(ima, imb, iia, iib, rna0, rnb0, rna1, rnb1)
            use = block_solver & two & ok
            W_[i + W_NX * L] = nx
            W_[i + W_NY * L] = ny
            W_[i + W_K11 * L] = k11 if two else 0.0
            W_[i + W_K22 * L] = k22 if two else 0.0
            W_[i + W_K12 * L] = k12 if two else 0.0
            W_[i + W_INVDET * L] = inv_det if use else 0.0
            W_[i + W_BLOCK * L] = 1.0 if use else 0.0
            # contact_soft.prepared_softness's terms
            ra = T[s + T_RA * L]
            rb = T[s + T_RB * L]
            rigid = (ima == 0.0) | (imb == 0.0)
            hz = contact_hertz(hz_static if rigid else hz_dyn, T[s + T_LOAD * L], ima, imb, ra, rb, h, g)
            rate, msc, isc = softness(hz, zeta, h)
            W_[i + W_RATE * L] = rate
            W_[i + W_MSC * L] = msc
            W_[i + W_ISC * L] = isc
            W_[i + W_DEEP * L] = DEEP * moving_size(ima, imb, ra, rb)
            W_[i + W_KE0 * L] = 0.0  # set by the first biased pass of a bouncy pair; none here
            W_[i + W_BOUNCY * L] = 0.0

