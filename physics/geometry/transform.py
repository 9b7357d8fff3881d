"""World-space geometry for the collision stages: vertices, normals, AABBs, per fixture."""
from __future__ import annotations

import math

from numba import prange

from .._jit import kernel
from ..threads import MIN_BODIES, share
from .norm import length
from ..store.bodies import STATIC
from ..store.fixtures import CHAIN_SEGMENT, CIRCLE
from ..store.slot_list import at


@kernel(forceinline=True)
def _fixture_box(F, V, f, px, py, c, s, margin):
    """Transform fixture f of a body at (px, py), angle (c, s); write and return its fattened AABB."""
    r = F.radius[f]
    if F.shape[f] == CIRCLE:
        lx = F.center[f, 0]
        ly = F.center[f, 1]
        wx = px + (c * lx - s * ly)
        wy = py + (s * lx + c * ly)
        F.wcenter[f, 0] = wx
        F.wcenter[f, 1] = wy
        return wx - r - margin, wy - r - margin, wx + r + margin, wy + r + margin
    lo_x = math.inf
    lo_y = math.inf
    hi_x = -math.inf
    hi_y = -math.inf
    for k in range(F.vstart[f], F.vstart[f] + F.vcount[f]):
        lx = V.local[k, 0]
        ly = V.local[k, 1]
        wx = px + c * lx - s * ly
        wy = py + s * lx + c * ly
        V.world[k, 0] = wx
        V.world[k, 1] = wy
        nx = V.normal[k, 0]
        ny = V.normal[k, 1]
        V.wnormal[k, 0] = c * nx - s * ny
        V.wnormal[k, 1] = s * nx + c * ny
        lo_x = min(lo_x, wx)
        lo_y = min(lo_y, wy)
        hi_x = max(hi_x, wx)
        hi_y = max(hi_y, wy)
    if F.shape[f] == CHAIN_SEGMENT:
        for g in range(2):
            lx = F.ghost[f, g, 0]
            ly = F.ghost[f, g, 1]
            F.wghost[f, g, 0] = px + c * lx - s * ly
            F.wghost[f, g, 1] = py + s * lx + c * ly
    if r > 0.0:  # a rounded core reaches r further (never added for sharp ones: bit-identical boxes)
        lo_x -= r
        lo_y -= r
        hi_x += r
        hi_y += r
    return lo_x - margin, lo_y - margin, hi_x + margin, hi_y + margin


@kernel
def _kept(B, F, f, i):
    """Fixture f's world geometry is what this step would compute again: its body is static
    (it never moves and has no velocity), or asleep and was already asleep when f was last
    computed (at rest since, with no velocity: waking or any edit makes it compute again)."""
    return B.kind[i] == STATIC or (B.awake[i] == 0 and F.awake[f] == 0)


@kernel(forceinline=True)
def _fixture(idx, k, full):
    """The k-th fixture visited: k itself when ``full`` (every fixture), else the list's."""
    return k if full else at(idx, k)


@kernel
def _clear_box(B, i):
    B.aabb[i, 0] = math.inf
    B.aabb[i, 1] = math.inf
    B.aabb[i, 2] = -math.inf
    B.aabb[i, 3] = -math.inf


@kernel(entry=True)
def update_geometry(B, F, V, n, nf, dt, spec, full, nthr, idx, m):
    """Transform the fixtures to world space and refresh the fixtures' and bodies' AABBs.

    Each AABB is fattened by m_i = spec/2 + dt (|v_i| + |w_i| r_i) of its body: two boxes
    then overlap whenever the bodies can come within the pair's speculative margin during
    the step, so the narrow phase never misses a fast pair.  A body's AABB is the union of
    its fixtures' (for the sandbox's overlays and queries); the fixtures also get the body's
    kind and awake flag, which the broad phase reads.

    Unless ``full`` (after an edit, or a change of dt or of the speculative distance, which
    the caller says), static and sleeping bodies keep their geometry (``_kept``): the same
    numbers, and a sleeping pile or a long static chain costs nothing here.  Then only the
    ``m`` fixtures listed in ``idx`` are visited (store/slot_list.py: ALL and ``nf``, or a list
    holding every fixture that is not kept, step/active.py).  The fixtures are transformed on
    ``nthr`` threads when there are many (each on its own: the same numbers); the bodies' boxes
    are their union after (``nthr`` None: the serial build, physics/threads.py).
    """
    if full:
        m = nf  # every fixture (the list is not read: _fixture)
    if not _split(B, F, V, idx, m, dt, spec, full, nthr):
        _boxes(B, F, V, idx, 0, m, dt, spec, full)
    if full:
        for i in range(n):
            _clear_box(B, i)
    else:  # a body's fixtures are all kept or none (they share the flags _kept reads)
        for k in range(m):
            f = at(idx, k)
            i = F.body[f]
            if not _kept(B, F, f, i):
                _clear_box(B, i)
    for k in range(m):
        f = _fixture(idx, k, full)
        i = F.body[f]
        if not full and _kept(B, F, f, i):
            continue
        F.kind[f] = B.kind[i]
        F.awake[f] = B.awake[i]
        B.aabb[i, 0] = min(B.aabb[i, 0], F.aabb[f, 0])
        B.aabb[i, 1] = min(B.aabb[i, 1], F.aabb[f, 1])
        B.aabb[i, 2] = max(B.aabb[i, 2], F.aabb[f, 2])
        B.aabb[i, 3] = max(B.aabb[i, 3], F.aabb[f, 3])


@kernel
def _split(B, F, V, idx, m, dt, spec, full, nthr):
    """_boxes split between ``nthr`` threads when there are enough fixtures; whether it did."""
    if nthr is not None:
        if nthr > 1 and m >= MIN_BODIES * nthr:
            _boxes_split(B, F, V, idx, m, dt, spec, full, nthr)
            return True
    return False


@kernel(parallel=True)
def _boxes_split(B, F, V, idx, m, dt, spec, full, nthr):
    for t in prange(nthr):
        lo, hi = share(m, t, nthr)
        _boxes(B, F, V, idx, lo, hi, dt, spec, full)


@kernel
def _boxes(B, F, V, idx, k0, k1, dt, spec, full):
    """The listed fixtures k0..k1-1 (``idx``, store/slot_list.py) in world space, their fattened
    boxes into F.aabb (kept ones skipped)."""
    for k in range(k0, k1):
        f = _fixture(idx, k, full)
        i = F.body[f]
        if not full and _kept(B, F, f, i):
            continue
        c = math.cos(B.q[i])
        s = math.sin(B.q[i])
        margin = 0.5 * spec + dt * (length(B.v[i, 0], B.v[i, 1]) + abs(B.w[i]) * B.bound_r[i])
        x0, y0, x1, y1 = _fixture_box(F, V, f, B.x[i, 0], B.x[i, 1], c, s, margin)
        F.aabb[f, 0] = x0
        F.aabb[f, 1] = y0
        F.aabb[f, 2] = x1
        F.aabb[f, 3] = y1
