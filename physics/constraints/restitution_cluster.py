"""Restitution never gains energy across bodies that bounce together (contact_restitution.py).

Each manifold's bounce is capped by the energy of its own pair at first touch (Stronge's bound,
per pair).  A body squeezed between two others belongs to two pairs, and its energy is counted
in both caps: three bodies meeting in one sub-step (a box at rest, a disc at -4 m/s, a box at
-6 m/s, e = 1; found by tests/test_property_scenes.py) left with 31.5 J from 24.3 J.

Here the bodies joined by the manifolds bouncing in one call form clusters (union-find over
dynamic bodies; a static or kinematic body joins nothing).  A cluster's kinetic energy after the
bounces must not exceed its energy at the start of the sub-step (``V0``: after gravity and
springs, before any contact impulse), which is what it had when these points first touched.
Where it does, every bounce impulse of that cluster is scaled by the largest s <= 1 that meets the
cap: the velocities are V_R + s (V - V_R), V_R those before the bounces, so the energy is a
quadratic in s.  A cluster within its cap (every lone bounce, which the pair cap already bounds)
is left exactly as it was.  Clusters with any e > 1 are not capped (the user asked for a gain).
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel
from ..store.union_find import find_root, union_roots
from ..store.slot_list import at
from .body_rows import II, IM, VX, VY, W
from .contact_soft import JN, PT

TOLERANCE = 1e-9  # relative: rounding of a bounce exactly at its pair cap is not a gain


@kernel
def save_velocities(SB, n, V):
    """V[:n] = the rows' (vx, vy, w)."""
    for i in range(n):
        _save(SB, i, V)


@kernel
def save_velocities_of(SB, idx, m, V):
    """``save_velocities`` of the ``m`` rows listed in ``idx`` (store/slot_list.py)."""
    for k in range(m):
        _save(SB, at(idx, k), V)


@kernel(forceinline=True)
def _save(SB, i, V):
    V[i, 0] = SB[i, VX]
    V[i, 1] = SB[i, VY]
    V[i, 2] = SB[i, W]


@kernel(forceinline=True)
def _energy(SB, i, vx, vy, w):
    e = 0.0
    if SB[i, IM] > 0.0:
        e += 0.5 * (vx * vx + vy * vy) / SB[i, IM]
    if SB[i, II] > 0.0:
        e += 0.5 * w * w / SB[i, II]
    return e


@kernel(forceinline=True)
def _dynamic(SB, i):
    return SB[i, IM] > 0.0 or SB[i, II] > 0.0


@kernel(runtime=True)
def clusters(SB, C, nc, n, due):
    """(parent array, member flags) of the dynamic bodies joined by the manifolds with ``due[k]``."""
    parent = np.arange(n)
    member = np.zeros(n, dtype=np.int8)
    for k in range(nc):
        if not due[k]:
            continue
        a = C.a[k]
        b = C.b[k]
        da = _dynamic(SB, a)
        db = _dynamic(SB, b)
        if da:
            member[a] = 1
        if db:
            member[b] = 1
        if da and db:
            union_roots(parent, a, b)
    return parent, member


@kernel(runtime=True)
def _scales(SB, C, nc, n, due, V0, VR, parent, member):
    """Per cluster root: the bounce scale s (1: within its cap)."""
    cap = np.zeros(n)
    e0 = np.zeros(n)
    lin = np.zeros(n)
    quad = np.zeros(n)
    for i in range(n):
        if member[i] == 0:
            continue
        r = find_root(parent, i)
        cap[r] += _energy(SB, i, V0[i, 0], V0[i, 1], V0[i, 2])
        e0[r] += _energy(SB, i, VR[i, 0], VR[i, 1], VR[i, 2])
        dx = SB[i, VX] - VR[i, 0]
        dy = SB[i, VY] - VR[i, 1]
        dw = SB[i, W] - VR[i, 2]
        im = SB[i, IM]
        ii = SB[i, II]
        if im > 0.0:
            lin[r] += (VR[i, 0] * dx + VR[i, 1] * dy) / im
            quad[r] += 0.5 * (dx * dx + dy * dy) / im
        if ii > 0.0:
            lin[r] += VR[i, 2] * dw / ii
            quad[r] += 0.5 * dw * dw / ii
    elastic = np.ones(n, dtype=np.int8)  # 0 where a manifold of the cluster asks for e > 1
    for k in range(nc):
        if due[k] and C.e[k] > 1.0:
            x = C.a[k] if _dynamic(SB, C.a[k]) else C.b[k]
            elastic[find_root(parent, x)] = 0
    s = np.ones(n)
    for r in range(n):
        if member[r] == 0 or parent[r] != r or elastic[r] == 0:
            continue
        if e0[r] + lin[r] + quad[r] <= cap[r] * (1.0 + TOLERANCE) + 1e-12 or quad[r] <= 0.0:
            continue
        disc = lin[r] * lin[r] - 4.0 * quad[r] * (e0[r] - cap[r])
        s[r] = min(1.0, max(0.0, (-lin[r] + math.sqrt(disc)) / (2.0 * quad[r]))) if disc > 0.0 else 0.0
    return s


@kernel(runtime=True)
def cap_clusters(SB, C, nc, n, R, due, V0, VR, J0):
    """Scale the bounces of every cluster whose energy they raised past its sub-step start.

    ``due[k]``: manifold k bounced in this call; ``VR``: the rows' velocities before it; ``J0``:
    the manifolds' normal impulses (2 points) before it."""
    parent, member = clusters(SB, C, nc, n, due)
    s = _scales(SB, C, nc, n, due, V0, VR, parent, member)
    for i in range(n):
        if member[i] == 0:
            continue
        f = s[find_root(parent, i)]
        if f < 1.0:
            SB[i, VX] = VR[i, 0] + f * (SB[i, VX] - VR[i, 0])
            SB[i, VY] = VR[i, 1] + f * (SB[i, VY] - VR[i, 1])
            SB[i, W] = VR[i, 2] + f * (SB[i, W] - VR[i, 2])
    for k in range(nc):
        if not due[k]:
            continue
        x = C.a[k] if _dynamic(SB, C.a[k]) else C.b[k]
        f = s[find_root(parent, x)]
        if f < 1.0:
            for q in range(C.count[k]):
                o = q * PT + JN
                R[k, o] = J0[k, q] + f * (R[k, o] - J0[k, q])
