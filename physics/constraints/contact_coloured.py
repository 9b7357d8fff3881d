"""The soft contact passes, colour by colour over the wide layout (Box2D v3's
b2SolveContactTwoPoints / b2WarmStartContactsTask over b2ContactConstraintWide).

The model of constraints/contact_soft.py (soft normal rows with bias, speculative rows, the 2x2
block solver of constraints/block.py, Coulomb friction, the first-touch speeds, largest impulses
and pair energy restitution needs), on the blocks of constraints/contact_wide.py.  Within a
colour no two manifolds share a moving body (constraints/colouring.py), so the LANES manifolds
of a block are solved side by side: the lane loop gathers both bodies' state, solves and leaves
the new velocities in float64 slots (``WV``), and a second, scalar loop scatters them back.  For
the lane loop to become vector code it must be straight-line: the block solver's four cases and
the sequential fallback are both computed and the answer selected (branches on data would stop
LLVM), array arguments are noalias (_jit.kernel_noalias) and the loops run from 0 over
per-colour slices (a ``range(s, e)`` index keeps numba's negative-index wraparound in the
address, which blocks vectorising).  Measured in ../shared/notes/solver-speed.md: ~10 ns per
manifold and pass against ~28 for a scalar pass over rows.

A pass solves the colours one after another (colouring.py's solve order), so a contact sees
the impulses of the colours before it (Gauss-Seidel); within a colour the order does not
matter, since its lanes share no moving body.  A fixed body (inverse mass and inertia zero) may appear in
several lanes of one colour: every lane writes back its unchanged velocity, so the writes agree.
"""
from __future__ import annotations

import numpy as np
from numba import prange

from .._jit import kernel, kernel_noalias
from ..threads import MIN_BLOCKS, share
from .body_rows import (DCOS as _DC, DPX as _DX, DPY as _DY, DSIN as _DS, II as _II, IM as _IM, VX as _VX,
                        VY as _VY, W as _W)
from .colouring import COUNT, FLAGS, IN_TURN, LANES, OVERFLOW, RUNS
from .contact_soft import deep_bias, friction_late
from .contact_wide import (BLOCK_SIZE, PW, V_SIZE, V_VAX, V_VAY, V_VBX, V_VBY, V_WA, V_WB, W_BLOCK, W_BOUNCY,
                           W_DEEP, W_INVDET, W_ISC, W_JN, W_JT, W_K11, W_K12, W_K22, W_KE0, W_MAXJ, W_MN, W_MSC,
                           W_MT, W_MU, W_NX, W_NY, W_RATE, W_RNA, W_RNB, W_RTA, W_RTB, W_SEP, W_VN0)

# body row offsets as uint64: an unsigned index has no negative-index wraparound code and
# uint64 + int64 would be float64 in numba
VX, VY, W, IM, II, DPX, DPY, DCOS, DSIN = (np.uint64(f) for f in (_VX, _VY, _W, _IM, _II, _DX, _DY, _DC, _DS))
L = LANES
P1 = PW * L  # offset of the second point's fields


@kernel(forceinline=True)
def _energy(vx, vy, w, im, ii):
    """Kinetic energy of a body (0 for a fixed one), as contact_soft._energy, without branches."""
    e = 0.5 * (vx * vx + vy * vy) / im if im > 0.0 else 0.0
    return e + (0.5 * w * w / ii if ii > 0.0 else 0.0)


@kernel(forceinline=True)
def _scatter(blk, lo, hi, WV, GA, GB, S):
    """The new velocities of lanes lo..hi-1 of block ``blk`` (in ``WV``) back into the body rows
    (scalar stores), before the next block reads them; lane by lane in the overflow colour, whose
    manifolds may share bodies (``seq``)."""
    o = blk * V_SIZE
    for l in range(lo, hi):
        i = o + l
        a = GA[blk * L + l]
        b = GB[blk * L + l]
        S[a + VX] = WV[i + V_VAX * L]
        S[a + VY] = WV[i + V_VAY * L]
        S[a + W] = WV[i + V_WA * L]
        S[b + VX] = WV[i + V_VBX * L]
        S[b + VY] = WV[i + V_VBY * L]
        S[b + W] = WV[i + V_WB * L]


@kernel_noalias
def warm_colour(nb, last, W_, WV, GA, GB, S, seq):
    """Warm start of ``nb`` blocks: every point's accumulated impulses applied.  ``seq`` None:
    the lanes side by side (one colour's full blocks); otherwise one after the other (the
    overflow colour, or a colour's last block that padding fills in part), and of the last block
    only its first ``last`` lanes (padding lanes hold nothing: contact_wide.py)."""
    for blk in range(nb):
        o = blk * BLOCK_SIZE
        m = L  # side by side: every lane (a constant trip count, one straight vector loop)
        if seq is not None and blk + 1 == nb:
            m = last  # lane after lane: the last block's real lanes only (numba prunes this for None)
        for l in range(m):
            i = o + l
            a = GA[blk * L + l]
            b = GB[blk * L + l]
            nx = W_[i + W_NX * L]
            ny = W_[i + W_NY * L]
            jn0 = W_[i + W_JN * L]
            jt0 = W_[i + W_JT * L]
            jn1 = W_[i + P1 + W_JN * L]
            jt1 = W_[i + P1 + W_JT * L]
            px = (jn0 * nx - jt0 * ny) + (jn1 * nx - jt1 * ny)
            py = (jn0 * ny + jt0 * nx) + (jn1 * ny + jt1 * nx)
            aa = (jn0 * W_[i + W_RNA * L] + jt0 * W_[i + W_RTA * L]) + \
                (jn1 * W_[i + P1 + W_RNA * L] + jt1 * W_[i + P1 + W_RTA * L])
            ab = (jn0 * W_[i + W_RNB * L] + jt0 * W_[i + W_RTB * L]) + \
                (jn1 * W_[i + P1 + W_RNB * L] + jt1 * W_[i + P1 + W_RTB * L])
            ima = S[a + IM]  # the inverse masses in float64, from the body rows: the same
            imb = S[b + IM]  # numbers on both sides of an impulse keep momentum exact
            v = blk * V_SIZE + l
            WV[v + V_VAX * L] = S[a + VX] - ima * px
            WV[v + V_VAY * L] = S[a + VY] - ima * py
            WV[v + V_WA * L] = S[a + W] - S[a + II] * aa
            WV[v + V_VBX * L] = S[b + VX] + imb * px
            WV[v + V_VBY * L] = S[b + VY] + imb * py
            WV[v + V_WB * L] = S[b + W] + S[b + II] * ab
            if seq is not None:
                _scatter(blk, l, l + 1, WV, GA, GB, S)
        if seq is None:
            _scatter(blk, 0, m, WV, GA, GB, S)


@kernel(forceinline=True)
def _bias(sep, inv_h, rate, deep, push, msc, isc, use_bias):
    """(bias, mass scale, impulse scale) of one normal row (contact_soft.py: speculative rows, deep_bias)."""
    spec = sep > 0.0
    if use_bias:
        return (sep * inv_h if spec else max(deep_bias(rate, sep, deep), -push), 1.0 if spec else msc,
                0.0 if spec else isc)
    return sep * inv_h if spec else 0.0, 1.0, 0.0


@kernel(forceinline=True)
def _friction(jn, old, mu, mass_t, rta, rtb, vax, vay, wa, vbx, vby, wb, nx, ny, anx, any_, bnx, bny, iia, iib,
              late):
    """One point's friction row: (new impulse, new velocities); none when ``late`` (left to the
    relax pass: contact_soft.friction_late).  Scalars only: an array argument of an inlined
    function leaves reference-count calls in the loop, which stop LLVM."""
    vt = -(vbx - vax) * ny + (vby - vay) * nx + wb * rtb - wa * rta
    limit = mu * jn
    new = old if late else min(max(old - mass_t * vt, -limit), limit)
    j = new - old
    return (new, vax + j * any_, vay - j * anx, wa - iia * j * rta, vbx - j * bny, vby + j * bnx,
            wb + iib * j * rtb)


@kernel_noalias
def solve_colour(nb, last, W_, WV, GA, GB, S, inv_h, push, use_bias, fp, seq):
    """One pass over ``nb`` blocks of one colour: per manifold the normal rows (2x2 block or
    sequential), then friction (``fp`` the friction_pass); ``use_bias`` False is the relax pass;
    ``last`` and ``seq`` as warm_colour's.
    The lane body is written out here, not in a helper: an array passed to an inlined function
    leaves reference-count calls in the loop, and a call stops LLVM from vectorising it."""
    for blk in range(nb):
        o = blk * BLOCK_SIZE
        m = L  # as warm_colour's
        if seq is not None and blk + 1 == nb:
            m = last
        for l in range(m):
            i = o + l
            a = GA[blk * L + l]
            b = GB[blk * L + l]
            nx = W_[i + W_NX * L]
            ny = W_[i + W_NY * L]
            ima = S[a + IM]  # float64, as warm_colour's
            imb = S[b + IM]
            iia = S[a + II]
            iib = S[b + II]
            vax = S[a + VX]
            vay = S[a + VY]
            wa = S[a + W]
            vbx = S[b + VX]
            vby = S[b + VY]
            wb = S[b + W]
            anx = ima * nx
            any_ = ima * ny
            bnx = imb * nx
            bny = imb * ny
            maxj0 = W_[i + W_MAXJ * L]
            maxj1 = W_[i + P1 + W_MAXJ * L]
            # every load unconditional and every choice a select: a load under a condition is not
            # known to be safe to speculate and keeps LLVM from vectorising the loop
            if use_bias:  # the pair's energy before it first pushes (restitution's cap)
                first = (W_[i + W_BOUNCY * L] != 0.0) & (maxj0 == 0.0) & (maxj1 == 0.0)
                ke = _energy(vax, vay, wa, ima, iia) + _energy(vbx, vby, wb, imb, iib)
                ke_old = W_[i + W_KE0 * L]
                W_[i + W_KE0 * L] = ke if first else ke_old
            ddn = (S[b + DPX] - S[a + DPX]) * nx + (S[b + DPY] - S[a + DPY]) * ny
            cam = S[a + DCOS] - 1.0
            cbm = S[b + DCOS] - 1.0
            sa = S[a + DSIN]
            sb = S[b + DSIN]
            rate = W_[i + W_RATE * L]
            msc = W_[i + W_MSC * L]
            isc = W_[i + W_ISC * L]
            deep = W_[i + W_DEEP * L]
            rna0 = W_[i + W_RNA * L]
            rnb0 = W_[i + W_RNB * L]
            rna1 = W_[i + P1 + W_RNA * L]
            rnb1 = W_[i + P1 + W_RNB * L]
            sep0 = (W_[i + W_SEP * L] + ddn + cbm * W_[i + W_RTB * L] + sb * rnb0
                    - cam * W_[i + W_RTA * L] - sa * rna0)
            sep1 = (W_[i + P1 + W_SEP * L] + ddn + cbm * W_[i + P1 + W_RTB * L] + sb * rnb1
                    - cam * W_[i + P1 + W_RTA * L] - sa * rna1)
            bias0, ms0, is0 = _bias(sep0, inv_h, rate, deep, push, msc, isc, use_bias)
            bias1, ms1, is1 = _bias(sep1, inv_h, rate, deep, push, msc, isc, use_bias)
            old0 = W_[i + W_JN * L]
            old1 = W_[i + P1 + W_JN * L]
            mn0 = W_[i + W_MN * L]
            mn1 = W_[i + P1 + W_MN * L]
            dvn = (vbx - vax) * nx + (vby - vay) * ny
            v0 = dvn + wb * rnb0 - wa * rna0
            v1 = dvn + wb * rnb1 - wa * rna1
            # the block solver (constraints/block.py solve_block): all four cases computed, one chosen
            k11 = W_[i + W_K11 * L]
            k22 = W_[i + W_K22 * L]
            k12 = W_[i + W_K12 * L]
            g0 = v0 - (k11 * old0 + k12 * old1) + bias0
            g1 = v1 - (k12 * old0 + k22 * old1) + bias1
            inv_det = W_[i + W_INVDET * L]
            xb0 = -ms0 * (k22 * g0 - k12 * g1) * inv_det
            xb1 = -ms0 * (k11 * g1 - k12 * g0) * inv_det
            xc0 = -ms0 * g0 * mn0
            xc1 = -ms0 * g1 * mn1
            c1 = (xb0 >= 0.0) & (xb1 >= 0.0)
            c2 = (xc0 >= 0.0) & (g1 + k12 * xc0 >= 0.0)
            c3 = (xc1 >= 0.0) & (g0 + k12 * xc1 >= 0.0)
            c4 = (g0 >= 0.0) & (g1 >= 0.0)
            x0 = xb0 if c1 else (xc0 if c2 else 0.0)
            x1 = xb1 if c1 else (0.0 if c2 else (xc1 if c3 else 0.0))
            done = (W_[i + W_BLOCK * L] != 0.0) & (ms0 == ms1) & (c1 | c2 | c3 | c4)
            # the sequential rows (Gauss-Seidel, point 0 then point 1), for when the block does not apply
            n0 = max(old0 + (-mn0 * ms0 * (v0 + bias0) - is0 * old0), 0.0)
            j = n0 - old0
            svax = vax - j * anx
            svay = vay - j * any_
            swa = wa - iia * j * rna0
            svbx = vbx + j * bnx
            svby = vby + j * bny
            swb = wb + iib * j * rnb0
            vn1 = (svbx - svax) * nx + (svby - svay) * ny + swb * rnb1 - swa * rna1
            n1 = max(old1 + (-mn1 * ms1 * (vn1 + bias1) - is1 * old1), 0.0)
            j = n1 - old1
            if use_bias:  # the normal speeds before the impulse, until a point first pushes
                vn0_old = W_[i + W_VN0 * L]
                vn1_old = W_[i + P1 + W_VN0 * L]
                W_[i + W_VN0 * L] = v0 if maxj0 == 0.0 else vn0_old
                W_[i + P1 + W_VN0 * L] = (v1 if done else vn1) if maxj1 == 0.0 else vn1_old
            d0 = x0 - old0
            d1 = x1 - old1
            d = d0 + d1
            vax = vax - d * anx if done else svax - j * anx
            vay = vay - d * any_ if done else svay - j * any_
            wa = wa - iia * (d0 * rna0 + d1 * rna1) if done else swa - iia * j * rna1
            vbx = vbx + d * bnx if done else svbx + j * bnx
            vby = vby + d * bny if done else svby + j * bny
            wb = wb + iib * (d0 * rnb0 + d1 * rnb1) if done else swb + iib * j * rnb1
            W_[i + W_JN * L] = x0 if done else n0
            W_[i + P1 + W_JN * L] = x1 if done else n1
            late = friction_late(fp, use_bias, mn1 != 0.0, ima, iia, imb, iib)  # mn1 0: one point
            for q in range(2):  # friction of both points (unrolled: q is 0 or 1)
                f = i + q * P1
                jn = W_[f + W_JN * L]
                W_[f + W_MAXJ * L] = max(W_[f + W_MAXJ * L], jn)
                jt, vax, vay, wa, vbx, vby, wb = _friction(jn, W_[f + W_JT * L], W_[f + W_MU * L], W_[f + W_MT * L],
                                                           W_[f + W_RTA * L], W_[f + W_RTB * L], vax, vay, wa, vbx,
                                                           vby, wb, nx, ny, anx, any_, bnx, bny, iia, iib, late)
                W_[f + W_JT * L] = jt
            v = blk * V_SIZE + l
            WV[v + V_VAX * L] = vax
            WV[v + V_VAY * L] = vay
            WV[v + V_WA * L] = wa
            WV[v + V_VBX * L] = vbx
            WV[v + V_VBY * L] = vby
            WV[v + V_WB * L] = wb
            if seq is not None:
                _scatter(blk, l, l + 1, WV, GA, GB, S)
        if seq is None:
            _scatter(blk, 0, m, WV, GA, GB, S)


WARM, SOLVE, RELAX = range(3)


@kernel
def coloured_pass(kind, bstart, W_, WV, GA, GB, SB, inv_h, push, fp, nthr):
    """One pass (WARM, SOLVE or RELAX) over the colours in use, in solve order (colouring.py's
    ``bstart``: the blocks, and the manifold counts that tell how many lanes of a colour's last
    block are real); ``fp`` the friction_pass.  A colour's full blocks are solved side by side
    in vector code, split between ``nthr`` threads when there are enough of them (None: the serial
    build, physics/threads.py); a last block that padding fills in part lane after lane over its real
    lanes only (the same numbers: its lanes share no moving body), so a small scene does not pay
    for eight lanes per manifold."""
    S = SB.reshape(SB.size)  # the body rows as one flat array (row offsets in GA, GB)
    in_turn = (bstart[FLAGS] & IN_TURN) != 0  # (a test flag: every colour lane after lane)
    for u in range(bstart[RUNS]):  # the colours in use only (most of the COLOURS are empty)
        r = bstart[RUNS + 1 + u]
        b0 = bstart[r]
        b1 = bstart[r + 1]
        last = bstart[COUNT + (OVERFLOW if r == 0 else r - 1)] - (b1 - b0 - 1) * L
        if r == 0 or in_turn:  # the overflow colour (colouring.py: first in solve order): lane after lane
            _blocks(kind, b0, b1, last, W_, WV, GA, GB, S, inv_h, push, fp, np.int64(1))
            continue
        bf = b1 if last == L else b1 - 1  # the full blocks
        if bf > b0 and not _split(kind, b0, bf, nthr, W_, WV, GA, GB, S, inv_h, push, fp):
            _blocks(kind, b0, bf, np.int64(L), W_, WV, GA, GB, S, inv_h, push, fp, None)
        if bf < b1:
            _blocks(kind, bf, b1, last, W_, WV, GA, GB, S, inv_h, push, fp, np.int64(1))


@kernel
def _split(kind, b0, b1, nthr, W_, WV, GA, GB, S, inv_h, push, fp):
    """Full blocks b0..b1-1 split between ``nthr`` threads when there are enough (_blocks_split);
    whether it did."""
    if nthr is not None:
        if nthr > 1 and b1 - b0 >= MIN_BLOCKS * nthr:
            _blocks_split(kind, b0, b1, nthr, W_, WV, GA, GB, S, inv_h, push, fp)
            return True
    return False


@kernel(parallel=True)
def _blocks_split(kind, b0, b1, nthr, W_, WV, GA, GB, S, inv_h, push, fp):
    """One colour's full blocks b0..b1-1 in ``nthr`` chunks, one per thread: the chunks share no
    moving body (a fixed one every lane leaves as it was), so any split gives the same numbers."""
    nb = b1 - b0
    for t in prange(nthr):
        lo, hi = share(nb, t, nthr)
        _blocks(kind, b0 + lo, b0 + hi, np.int64(L), W_, WV, GA, GB, S, inv_h, push,
                fp, None)


@kernel
def _blocks(kind, b0, b1, last, W_, WV, GA, GB, S, inv_h, push, fp, seq):
    """Blocks b0..b1-1 of one colour, handed over as slices that start at 0 (``seq``, ``last``:
    warm_colour's)."""
    Wc = W_[b0 * BLOCK_SIZE:b1 * BLOCK_SIZE]
    Vc = WV[b0 * V_SIZE:b1 * V_SIZE]
    ga = GA[b0 * L:b1 * L]
    gb = GB[b0 * L:b1 * L]
    if kind == WARM:
        warm_colour(b1 - b0, last, Wc, Vc, ga, gb, S, seq)
    else:
        solve_colour(b1 - b0, last, Wc, Vc, ga, gb, S, inv_h, push, kind == SOLVE, fp, seq)
