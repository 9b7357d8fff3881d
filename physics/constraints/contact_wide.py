"""The contact rows in Box2D v3's wide layout (b2ContactConstraintWide, contact_solver.c).

The coloured solve (constraints/contact_coloured.py) works on blocks of LANES manifolds of one
colour (constraints/colouring.py).  A block is NW fields of LANES values each, all blocks in
one flat array: field f of lane l of block b is ``W[(b * NW + f) * LANES + l]``.  Constant
strides and one base pointer are what let LLVM turn the lane loop into vector code (a 2-D
``[field, slot]`` array never vectorised: ../shared/notes/solver-speed.md).  The fields are the
scratch rows' (constraints/contact_soft.py, ``R``) that a pass reads or writes.  A lane leaves
its bodies' new velocities for the scalar scatter in ``WV``, VW float64 slots per lane laid out
as the blocks (``WV[(b * VW + v) * LANES + l]``), and reads the inverse masses from the float64
body rows: velocities and masses kept in float64 keep linear momentum exact (through float32
slots a pass lost 5e-8 of it, and a squeeze gained 4e-8 of its energy).

constraints/contact_prepare.py prepares a step's manifolds straight into the blocks (the same
terms as contact_soft.prepare_contacts, through its helpers; it stages its inputs in ``WV``'s
tail, after the velocities) and ``store_wide`` hands the impulses back to the contact table: a step without a bouncy contact never writes the rows ``R``.  Restitution works
on the rows, so a step with a bouncy contact prepares ``R`` and ``pack`` copies it into the blocks;
``unpack`` copies what the passes accumulated (impulses, first-touch speeds, largest impulses,
energy) back into ``R`` for restitution and the store, in a sub-step where ``bounce_due`` finds a
point that may bounce; ``repack_normal`` takes restitution's impulses back.  Padding lanes
(``order`` -1, only in a colour's last block) are never read: the passes solve a last block over
its real lanes only (contact_coloured.coloured_pass).
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from .body_rows import NB
from .colouring import LANES
from .contact_soft import (BLOCK, INV_DET, JN, JT, K11, K12, K22, KE0 as R_KE0, MASS_N, MASS_T, MAXJ, MU,
                           NX as R_NX, NY as R_NY, PT, RNA, RNB, RTA, RTB, SEP0, SOFT, VN0, DEEPD)

# per point q the fields start at q * PW
W_RNA, W_RNB, W_RTA, W_RTB, W_MN, W_MT, W_SEP, W_MU, W_VN0, W_MAXJ, W_JN, W_JT = range(12)
PW = 12
_M = 2 * PW
(W_NX, W_NY, W_K11, W_K22, W_K12, W_INVDET, W_BLOCK, W_RATE, W_MSC, W_ISC, W_KE0, W_BOUNCY,
 W_DEEP) = range(_M, _M + 13)
NW = _M + 13
BLOCK_SIZE = NW * LANES  # floats per block
V_VAX, V_VAY, V_WA, V_VBX, V_VBY, V_WB = range(6)  # a lane's new velocities in WV
VW = 6
V_SIZE = VW * LANES  # WV's floats per block



@kernel(forceinline=True)
def _at(j, f):
    """Index of field f of slot j (j >= 0: unsigned arithmetic, no floor-division fix-ups)."""
    u = np.uint64(j)
    return np.int64((u // np.uint64(LANES) * np.uint64(NW) + np.uint64(f)) * np.uint64(LANES)
                    + u % np.uint64(LANES))


@kernel
def pack(C, R, order, slots, block_solver, W, GA, GB):
    """W, GA, GB (body row offsets into the flat body rows: row * NB) for the slots 0..slots-1."""
    for j in range(slots):
        k = order[j]
        if k < 0:  # padding
            continue
        o = _at(j, 0)  # field f of slot j at o + f * LANES
        a = C.a[k]
        b = C.b[k]
        GA[j] = a * NB
        GB[j] = b * NB
        cnt = C.count[k]
        for q in range(2):
            po = o + q * PW * LANES
            rq = q * PT
            if q < cnt:
                W[po + W_RNA * LANES] = R[k, rq + RNA]
                W[po + W_RNB * LANES] = R[k, rq + RNB]
                W[po + W_RTA * LANES] = R[k, rq + RTA]
                W[po + W_RTB * LANES] = R[k, rq + RTB]
                W[po + W_MN * LANES] = R[k, rq + MASS_N]
                W[po + W_MT * LANES] = R[k, rq + MASS_T]
                W[po + W_SEP * LANES] = R[k, rq + SEP0]
                W[po + W_MU * LANES] = R[k, rq + MU]
                W[po + W_VN0 * LANES] = R[k, rq + VN0]
                W[po + W_MAXJ * LANES] = R[k, rq + MAXJ]
                W[po + W_JN * LANES] = R[k, rq + JN]
                W[po + W_JT * LANES] = R[k, rq + JT]
            else:
                for f in range(PW):
                    W[po + f * LANES] = 0.0
        W[o + W_NX * LANES] = R[k, R_NX]
        W[o + W_NY * LANES] = R[k, R_NY]
        W[o + W_K11 * LANES] = R[k, K11]
        W[o + W_K22 * LANES] = R[k, K22]
        W[o + W_K12 * LANES] = R[k, K12]
        use = block_solver and cnt == 2 and R[k, BLOCK] != 0.0
        W[o + W_INVDET * LANES] = R[k, INV_DET] if use else 0.0
        W[o + W_BLOCK * LANES] = 1.0 if use else 0.0
        W[o + W_RATE * LANES] = R[k, SOFT]
        W[o + W_MSC * LANES] = R[k, SOFT + 1]
        W[o + W_ISC * LANES] = R[k, SOFT + 2]
        W[o + W_DEEP * LANES] = R[k, DEEPD]
        W[o + W_KE0 * LANES] = R[k, R_KE0]
        W[o + W_BOUNCY * LANES] = 1.0 if C.e[k] != 0.0 else 0.0


@kernel
def store_wide(C, W, order, slots):
    """The blocks' accumulated impulses into the contact table (next step's warm start), as
    ``unpack`` then contact_soft.store_impulses leave them."""
    for j in range(slots):
        k = order[j]
        if k < 0:
            continue
        for q in range(C.count[k]):
            C.jn[k, q] = W[_at(j, q * PW + W_JN)]
            C.jt[k, q] = W[_at(j, q * PW + W_JT)]


@kernel
def unpack(C, W, order, slots, R):
    """What the passes changed back into R: per point JN, JT, VN0, MAXJ, and KE0."""
    for j in range(slots):
        k = order[j]
        if k < 0:
            continue
        for q in range(C.count[k]):
            o = q * PT
            R[k, o + JN] = W[_at(j, q * PW + W_JN)]
            R[k, o + JT] = W[_at(j, q * PW + W_JT)]
            R[k, o + VN0] = W[_at(j, q * PW + W_VN0)]
            R[k, o + MAXJ] = W[_at(j, q * PW + W_MAXJ)]
        R[k, R_KE0] = W[_at(j, W_KE0)]


@kernel
def repack_normal(C, R, order, slots, W):
    """Restitution's normal impulses (it works on R) back into the blocks."""
    for j in range(slots):
        k = order[j]
        if k < 0:
            continue
        for q in range(C.count[k]):
            W[_at(j, q * PW + W_JN)] = R[k, q * PT + JN]


@kernel
def bounce_due(W, order, slots, threshold):
    """Whether a bouncy manifold may be due to bounce (contact_restitution._due without its
    BOUNCED flag, which lives in R): a point that pushed and first touched faster than
    ``threshold``.  False: restitution would do nothing, so the rows need not be handed over."""
    for j in range(slots):
        if order[j] < 0 or W[_at(j, W_BOUNCY)] == 0.0:
            continue
        for q in range(2):
            if W[_at(j, q * PW + W_MAXJ)] > 0.0 and W[_at(j, q * PW + W_VN0)] < -threshold:
                return True
    return False
