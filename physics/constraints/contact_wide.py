"""The contact rows in Box2D v3's wide layout (b2ContactConstraintWide, contact_solver.c).

The coloured solve (constraints/contact_coloured.py) works on blocks of LANES manifolds of one
colour (constraints/colouring.py).  A block is NW fields of LANES values each, all blocks in
one flat array: field f of lane l of block b is ``W[(b * NW + f) * LANES + l]``.  Constant
strides and one base pointer are what let LLVM turn the lane loop into vector code (a 2-D
``[field, slot]`` array never vectorised: ../shared/notes/solver-speed.md).  The fields are the
scratch rows' (constraints/contact_soft.py, ``R``) that a pass reads or writes, plus the bodies'
inverse masses (read once per step instead of once per pass) and six slots where a lane leaves
its bodies' new velocities for the scalar scatter.

``pack`` copies the prepared rows into the blocks once per step; ``unpack`` copies what the
passes accumulated (impulses, first-touch speeds, largest impulses, energy) back into ``R`` for
restitution and the store; ``repack_normal`` takes restitution's impulses back.  A padding lane
is all zeros (no mass: its impulses stay zero) and reads and writes one spare body row.
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from .body_rows import II, IM, NB
from .colouring import LANES
from .contact_soft import (BLOCK, INV_DET, JN, JT, K11, K12, K22, KE0 as R_KE0, MASS_N, MASS_T, MAXJ, MU,
                           NX as R_NX, NY as R_NY, PT, RNA, RNB, RTA, RTB, SEP0, SOFT, VN0)

# per point q the fields start at q * PW
W_RNA, W_RNB, W_RTA, W_RTB, W_MN, W_MT, W_SEP, W_MU, W_VN0, W_MAXJ, W_JN, W_JT = range(12)
PW = 12
_M = 2 * PW
(W_NX, W_NY, W_K11, W_K22, W_K12, W_INVDET, W_BLOCK, W_RATE, W_MSC, W_ISC, W_KE0, W_BOUNCY,
 W_IMA, W_IMB, W_IIA, W_IIB, W_VAX, W_VAY, W_WA, W_VBX, W_VBY, W_WB) = range(_M, _M + 22)
NW = _M + 22
BLOCK_SIZE = NW * LANES  # floats per block

# (wide field, row field) of each point, and of the manifold, copied by pack / unpack
_POINT = ((W_RNA, RNA), (W_RNB, RNB), (W_RTA, RTA), (W_RTB, RTB), (W_MN, MASS_N), (W_MT, MASS_T),
          (W_SEP, SEP0), (W_MU, MU), (W_VN0, VN0), (W_MAXJ, MAXJ), (W_JN, JN), (W_JT, JT))


def wide_arrays(slots: int, dtype=np.float64):
    """(W, GA, GB) for ``slots`` slots (a multiple of LANES)."""
    return (np.zeros(slots // LANES * BLOCK_SIZE, dtype), np.zeros(slots, np.uint64),
            np.zeros(slots, np.uint64))


@kernel(inline="always")
def _at(j, f):
    """Index of field f of slot j."""
    return (j // LANES * NW + f) * LANES + j % LANES


@kernel
def pack(C, R, SB, order, slots, pad_row, block_solver, W, GA, GB):
    """W, GA, GB (body row offsets into the flat SB: row * NB) for the slots 0..slots-1."""
    for j in range(slots):
        k = order[j]
        if k < 0:
            for f in range(NW):
                W[_at(j, f)] = 0.0
            GA[j] = pad_row * NB
            GB[j] = pad_row * NB
            continue
        a = C.a[k]
        b = C.b[k]
        GA[j] = a * NB
        GB[j] = b * NB
        for q in range(2):
            for wf, rf in _POINT:
                W[_at(j, q * PW + wf)] = R[k, q * PT + rf] if q < C.count[k] else 0.0
        W[_at(j, W_NX)] = R[k, R_NX]
        W[_at(j, W_NY)] = R[k, R_NY]
        W[_at(j, W_K11)] = R[k, K11]
        W[_at(j, W_K22)] = R[k, K22]
        W[_at(j, W_K12)] = R[k, K12]
        use = block_solver and C.count[k] == 2 and R[k, BLOCK] != 0.0
        W[_at(j, W_INVDET)] = R[k, INV_DET] if use else 0.0
        W[_at(j, W_BLOCK)] = 1.0 if use else 0.0
        W[_at(j, W_RATE)] = R[k, SOFT]
        W[_at(j, W_MSC)] = R[k, SOFT + 1]
        W[_at(j, W_ISC)] = R[k, SOFT + 2]
        W[_at(j, W_KE0)] = R[k, R_KE0]
        W[_at(j, W_BOUNCY)] = 1.0 if C.e[k] != 0.0 else 0.0
        W[_at(j, W_IMA)] = SB[a, IM]
        W[_at(j, W_IMB)] = SB[b, IM]
        W[_at(j, W_IIA)] = SB[a, II]
        W[_at(j, W_IIB)] = SB[b, II]


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
