"""The narrow-phase kernel: every broad-phase fixture pair -> sorted contact rows.

Pairs are oriented by stable fixture id (a = the lower id), so a row's key
(id_a << 32) | id_b and its features survive slot changes from removals (a
world of one-fixture bodies numbers its fixtures as its bodies: the same keys,
order and results as before fixtures); the row's ``a``/``b`` are the fixtures'
body slots, which is all the solvers read;
pairs are visited in key order, so rows come out sorted and the warm-start
lookup is a merge walk.  Each pair is computed in coordinates relative to
a's centre of mass: world coordinates 10 km out would otherwise cost
log10(1e4) digits of every depth (the shapes themselves are small).
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from ...geometry.norm import length
from ...geometry.shapes import MAX_POLYGON_VERTICES
from ...store.fixtures import CHAIN_SEGMENT, CIRCLE, POLYGON
from ..argsort import argsort_into
from ..reach import may_touch
from .carry import carry_over, seek
from .chain import chain_circle, chain_polygon
from .circles import circle_circle, polygon_circle
from .pair import polygon_pair, sat_pair
from .rounded import round_pair

BIAS = 1e-3          # reference-face hysteresis, relative to the smaller body


@kernel(runtime=True, forceinline=True)
def pair_keys(F, pairs, npairs):
    """Keys of the fixture pairs oriented by id (lower id first)."""
    keys = np.empty(npairs, np.int64)
    # F.id bound once: each F.id in the loop would be a reference-count pair (runtime on here)
    pair_keys_into(F.id, pairs, npairs, keys)
    return keys


@kernel(forceinline=True)
def pair_keys_into(fid, pairs, npairs, keys):
    """``pair_keys`` into ``keys`` (``fid``: the fixtures' ids)."""
    for k in range(npairs):
        ia = fid[pairs[k, 0]]
        ib = fid[pairs[k, 1]]
        if ia > ib:
            ia, ib = ib, ia
        keys[k] = (ia << 32) | ib


@kernel(forceinline=True)
def pair_margin(B, a, b, dt, spec):
    """spec + dt (|v_a - v_b| + |w_a| r_a + |w_b| r_b): how close can get in a step."""
    dv = length(B.v[a, 0] - B.v[b, 0], B.v[a, 1] - B.v[b, 1])
    return spec + dt * (dv + abs(B.w[a]) * B.bound_r[a] + abs(B.w[b]) * B.bound_r[b])


@kernel(forceinline=True)
def _relative(V, F, i, ox, oy, out):
    """Core vertices of fixture i shifted by -(ox, oy) into ``out``; returns how many (the caller
    slices ``out``: a kernel compiled without numba's runtime cannot hand back an array view)."""
    s = F.vstart[i]
    n = F.vcount[i]
    for k in range(n):
        out[k, 0] = V.world[s + k, 0] - ox
        out[k, 1] = V.world[s + k, 1] - oy
    return n


@kernel(forceinline=True)
def _manifold(B, F, V, fa, fb, a, b, method, full, margin, sc_a, sc_b, sw, si, lam, poly, out_p, out_s, out_f):
    """Dispatch on the fixtures' shape pair; points are relative to body a's centre.

    Circles and sharp polygons take the paths they took before fixtures (bit for bit);
    any pair with a rounded core (rounded polygon, capsule, segment) takes rounded.py.

    This dispatch is inlined into the pair loop; the pair routines it calls (``sat_pair``,
    ``polygon_pair``, ``round_pair``, the chain pairs, ``polygon_circle``) are functions of their
    own (pair.py's module doc).  Inlined, the rounded, chain and circle pairs made ``_rows``
    one function so large that numba's type inference of it was most of a cold launch (the
    narrow-phase unit: 43 -> 21 CPU s, docs/internals.md "Compile time"), for a call that costs
    a few ns against the hundreds of ns such a pair takes (bench/results/launch.md).

    ``full`` None: the lean kernel, compiled without GJK, EPA, the rounded and the chain pairs
    (numba prunes the branches on the argument's type, as the solvers do for a world without
    joints): SAT for sharp polygons, and circles against anything.  It returns count -1 for a
    pair it does not handle, and the caller runs the whole kernel instead (``collide``).  Half
    of the narrow phase's compile time is in what it leaves out.
    """
    ox, oy = B.x[a, 0], B.x[a, 1]
    ta, tb = F.shape[fa], F.shape[fb]
    if ta == CHAIN_SEGMENT or tb == CHAIN_SEGMENT:
        if full is None:
            return -1, 0.0, 0.0
        return _chain(B, F, V, fa, fb, a, b, ox, oy, margin, sc_a, sc_b, out_p, out_s, out_f)
    if ta == CIRCLE and tb == CIRCLE:
        return circle_circle(F.wcenter[fa, 0] - ox, F.wcenter[fa, 1] - oy, F.radius[fa],
                             F.wcenter[fb, 0] - ox, F.wcenter[fb, 1] - oy, F.radius[fb], margin, out_p, out_s, out_f)
    if ta == CIRCLE or tb == CIRCLE:
        # one call site for both orders (compile time); the kernel's normal
        # goes core -> circle, so flip it when the circle is a
        p, c = (fa, fb) if tb == CIRCLE else (fb, fa)
        vp = sc_a[:_relative(V, F, p, ox, oy, sc_a)]
        np_ = V.wnormal[F.vstart[p]:F.vstart[p] + F.vcount[p]]
        rp = F.radius[p]
        cnt, nx, ny = polygon_circle(vp, np_, F.wcenter[c, 0] - ox, F.wcenter[c, 1] - oy, F.radius[c] + rp,
                                     margin, out_p, out_s, out_f)
        if rp > 0.0:  # a rounded core's surface is rp further out: the midpoint moves by rp
            for k in range(cnt):
                out_p[k, 0] += rp * nx
                out_p[k, 1] += rp * ny
        if c == fa:
            return cnt, -nx, -ny
        return cnt, nx, ny
    vb = sc_b[:_relative(V, F, fb, ox, oy, sc_b)]
    nb = V.wnormal[F.vstart[fb]:F.vstart[fb] + F.vcount[fb]]
    va = sc_a[:_relative(V, F, fa, ox, oy, sc_a)]
    na = V.wnormal[F.vstart[fa]:F.vstart[fa] + F.vcount[fa]]
    bias = BIAS * min(B.bound_r[a], B.bound_r[b])
    if ta == POLYGON and tb == POLYGON and F.radius[fa] == 0.0 and F.radius[fb] == 0.0:
        if full is None:
            return sat_pair(va, na, vb, nb, margin, bias, out_p, out_s, out_f)
        return polygon_pair(va, na, vb, nb, method, margin, bias, sw, si, lam, poly, out_p, out_s, out_f)
    if full is None:
        return -1, 0.0, 0.0
    return round_pair(va, na, F.radius[fa], vb, nb, F.radius[fb], margin, bias, out_p, out_s, out_f)


@kernel(forceinline=True)
def _chain(B, F, V, fa, fb, a, b, ox, oy, margin, sc_a, sc_b, out_p, out_s, out_f):
    """A chain segment against any shape (chain.py); the normal is flipped when the chain is b."""
    s, o = (fa, fb) if F.shape[fa] == CHAIN_SEGMENT else (fb, fa)
    vs = sc_a[:_relative(V, F, s, ox, oy, sc_a)]
    g = sc_a[2:4]
    for k in range(2):
        g[k, 0] = F.wghost[s, k, 0] - ox
        g[k, 1] = F.wghost[s, k, 1] - oy
    if F.shape[o] == CIRCLE:
        cnt, nx, ny = chain_circle(vs, g, F.wcenter[o, 0] - ox, F.wcenter[o, 1] - oy, F.radius[o], margin,
                                   out_p, out_s, out_f)
    else:
        vo = sc_b[:_relative(V, F, o, ox, oy, sc_b)]
        ns = V.wnormal[F.vstart[s]:F.vstart[s] + 2]
        no = V.wnormal[F.vstart[o]:F.vstart[o] + F.vcount[o]]
        bias = BIAS * min(B.bound_r[a], B.bound_r[b])
        cnt, nx, ny = chain_polygon(vs, ns, g, vo, no, F.radius[o], margin, bias, out_p, out_s, out_f)
    if s == fb:
        return cnt, -nx, -ny
    return cnt, nx, ny


@kernel(forceinline=True)
def _write_row(C, row, B, F, fa, fb, a, b, key, count, nx, ny, out_p, out_s, out_f):
    ox, oy = B.x[a, 0], B.x[a, 1]
    C.a[row] = a
    C.b[row] = b
    C.key[row] = key
    C.count[row] = count
    C.normal[row, 0] = nx
    C.normal[row, 1] = ny
    for p in range(2):
        live = p < count
        C.point[row, p, 0] = out_p[p, 0] + ox if live else 0.0
        C.point[row, p, 1] = out_p[p, 1] + oy if live else 0.0
        C.depth[row, p] = -out_s[p] if live else 0.0
        C.feature[row, p] = out_f[p] if live else -1
    # combined materials of the two fixtures: the bouncier surface wins; friction is a geometric mean
    C.e[row] = max(F.e[fa], F.e[fb])
    C.mu_s[row] = math.sqrt(F.mu_s[fa] * F.mu_s[fb])
    C.mu_d[row] = math.sqrt(F.mu_d[fa] * F.mu_d[fb])


@kernel(entry=True, runtime=True)
def manifold_scratch():
    """The scratch arrays one ``_manifold`` call works in (support cores, simplex, clip polygon,
    output points), allocated once per kernel call and reused for every pair."""
    return (np.empty((MAX_POLYGON_VERTICES, 2)), np.empty((MAX_POLYGON_VERTICES, 2)), np.empty((3, 2)),
            np.empty((3, 2), np.int64), np.empty(3), np.empty((2 * MAX_POLYGON_VERTICES + 4, 2)),
            np.zeros((2, 2)), np.zeros(2), np.zeros(2, np.int32))


@kernel(runtime=True, forceinline=True)
def _order_into(keys, n, order):
    """The ascending order of keys[:n] into ``order``: a merge sort, unless the keys already
    ascend.  They do while the fixtures' slots follow their ids (no removal yet): the broad
    phase's pairs come sorted by slot.  The keys of distinct pairs are distinct, so both give
    the one order there is."""
    for k in range(1, n):
        if keys[k] <= keys[k - 1]:
            argsort_into(keys, n, order, np.empty(n, np.int64))
            return
    for k in range(n):
        order[k] = k


@kernel(runtime=True)
def sort_pairs(fid, pairs, npairs, keys, order):
    """The pairs' keys (``pair_keys``; ``fid``: the fixtures' ids) into ``keys`` and their
    ascending order into ``order``, both at least ``npairs`` long, without allocating for a small
    world: an insertion sort up to 32 pairs (the keys are distinct, so any sort gives this
    order), ``_order_into`` beyond."""
    pair_keys_into(fid, pairs, npairs, keys)
    if npairs > 32:
        _order_into(keys, npairs, order)
        return
    for k in range(npairs):
        j = k
        while j > 0 and keys[order[j - 1]] > keys[k]:
            order[j] = order[j - 1]
            j -= 1
        order[j] = k


@kernel(entry=True)
def _rows(B, F, V, pairs, order, keys, C, P, n_prev, method, full, dt, spec, row, ptr,
          sc_a, sc_b, sw, si, lam, poly, out_p, out_s, out_f):
    """The rows of the pairs ``order`` (in key order) from row ``row`` on, the previous step's rows
    searched from ``ptr`` (carry.py); returns the row after the last, or -1 when the lean kernel
    (``full`` None) met a pair it leaves out."""
    for k in order:
        fa, fb = pairs[k, 0], pairs[k, 1]
        if F.id[fa] > F.id[fb]:
            fa, fb = fb, fa
        a, b = F.body[fa], F.body[fb]
        if not may_touch(B, a, b, dt, spec):
            continue
        margin = pair_margin(B, a, b, dt, spec)
        count, nx, ny = _manifold(B, F, V, fa, fb, a, b, method, full, margin, sc_a, sc_b, sw, si, lam, poly,
                                  out_p, out_s, out_f)
        if count < 0:
            return -1       # the lean kernel met a pair it leaves out: the caller runs the whole one
        if count == 0:
            continue
        _write_row(C, row, B, F, fa, fb, a, b, keys[k], count, nx, ny, out_p, out_s, out_f)
        ptr = seek(P, n_prev, ptr, keys[k])
        carry_over(C, row, P, n_prev, ptr)
        row += 1
    return row
