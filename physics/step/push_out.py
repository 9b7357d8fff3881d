"""The energy guard's push-out allowance: the energy push-out may add in a step.

Bodies created or moved inside each other are pushed apart, and push-out may add only the
energy of separating the overlap it found.  A manifold k of depth d_k > 0 between bodies a and
b separates at up to the mode's push-out speed v_p (SolverMode.push_speed) and lifts the pair
apart by at most d_k against gravity, which takes m_k (v_p^2 / 2 + |g| d_k) with
m_k = 1 / (1/m_a + 1/m_b) (``pair_mass``).  Pushes add up along a chain of overlapping
contacts, though: a column of n bodies created inside each other on the ground leaves at up to
n v_p at its top.  Within a cluster of dynamic bodies joined by overlapping manifolds (union-find
over the contacts), any body is at most P = (bodies - 1) contacts from any other, plus one from
the static or kinematic body the cluster rests on, so its push-out speed is at most P v_p, and
the allowance per manifold is m_k ((P v_p)^2 / 2 + |g| d_k).  A lone pair has P = 1: the
contact's own m_k v_p^2 / 2.  A light body overlapping a heavy one brings only its own mass
(m_k <= the lighter mass), not the heavy body's.  Not covered, and refused when the guard sees it:
a light body created between two heavy ones, which pushes them apart at v_p each (the heavy
bodies' energy, m_k of each manifold being the light body's).
"""
from __future__ import annotations

import math
from collections import Counter

import numpy as np

from .._jit import kernel
from ..store.slot_list import at

#: rows of the int scratch ``cluster`` (3 x bodies): union-find parents, dynamic bodies per
#: cluster root, and whether the cluster touches a body that does not move (1)
PARENT, BODIES, FIXED = range(3)


@kernel
def pair_mass(B, a, b):
    """1 / (1/m_a + 1/m_b) of a contact's two bodies (kg; a static or kinematic body's inverse
    mass is 0); 0 when neither moves.  A point's effective mass along the normal,
    1 / (1/m_a + 1/m_b + (r_a x n)^2 / I_a + (r_b x n)^2 / I_b), is at most this, and the
    least kinetic energy that gives both points of a face the normal speed v is at most that of
    the pure translation, 1/2 m_ab v^2: so this mass bounds a manifold, not only a point."""
    w = B.inv_m[a] + B.inv_m[b]
    return 1.0 / w if w > 0.0 else 0.0


@kernel
def overlap(npts, depth, k):
    """The deepest overlap (m) of manifold k; <= 0 when it does not overlap (speculative)."""
    d = depth[k, 0]
    if npts[k] > 1:
        d = max(d, depth[k, 1])
    return d


@kernel
def _root(cluster, i):
    """The root of i's set in the union-find row PARENT (halving the path on the way; as
    store/union_find.py, on a row of the scratch)."""
    while cluster[PARENT, i] != i:
        cluster[PARENT, i] = cluster[PARENT, cluster[PARENT, i]]
        i = cluster[PARENT, i]
    return i


@kernel
def _clusters(B, idx, m, Ca, Cb, npts, depth, nc, cluster):
    """Union-find of the bodies over the overlapping manifolds between two moving bodies;
    then per root the moving bodies in its set and whether an overlapping manifold ties the set
    to a body that does not move.  Visits the ``m`` bodies listed in ``idx`` (store/slot_list.py),
    which must hold every body of the manifolds: a body in none is its own set, never read."""
    for k in range(m):
        i = at(idx, k)
        cluster[PARENT, i] = i
        cluster[BODIES, i] = 0
        cluster[FIXED, i] = 0
    for k in range(nc):
        a, b = Ca[k], Cb[k]
        if overlap(npts, depth, k) > 0.0 and B.inv_m[a] > 0.0 and B.inv_m[b] > 0.0:
            ra, rb = _root(cluster, a), _root(cluster, b)
            cluster[PARENT, max(ra, rb)] = min(ra, rb)
    for k in range(m):
        i = at(idx, k)
        if B.inv_m[i] > 0.0:
            cluster[BODIES, _root(cluster, i)] += 1
    for k in range(nc):
        a, b = Ca[k], Cb[k]
        if overlap(npts, depth, k) > 0.0 and (B.inv_m[a] == 0.0 or B.inv_m[b] == 0.0):
            cluster[FIXED, _root(cluster, a if B.inv_m[a] > 0.0 else b)] = 1


@kernel
def push_sum(B, idx, m, Ca, Cb, npts, depth, nc, speed, g, cluster):
    """The push-out allowance of the ``nc`` manifolds (J; see the module doc): ``speed`` the
    mode's push-out speed cap (m/s), ``g`` = |gravity|, ``cluster`` int scratch (3, >= n); the
    bodies ``_clusters`` visits listed in ``idx``."""
    _clusters(B, idx, m, Ca, Cb, npts, depth, nc, cluster)
    total = 0.0
    for k in range(nc):
        d = overlap(npts, depth, k)
        m = pair_mass(B, Ca[k], Cb[k])
        if d <= 0.0 or m == 0.0:
            continue
        r = _root(cluster, Ca[k] if B.inv_m[Ca[k]] > 0.0 else Cb[k])
        v = (cluster[BODIES, r] - 1 + cluster[FIXED, r]) * speed
        total += m * (0.5 * v * v + g * d)
    return total


def push_allowance(world) -> float:
    """``push_sum`` of the world's current contact table, in numpy and Python: the reference that
    tests and tools compare the step's figure with (J)."""
    store = world._store
    C, nc = store.contacts.cur, store.contacts.n
    inv = store.bodies.view.inv_m[:store.bodies.n]
    a, b = C.a[:nc].astype(np.int64), C.b[:nc].astype(np.int64)
    depth = np.where(C.count[:nc] > 1, C.depth[:nc].max(1, initial=-np.inf), C.depth[:nc, 0])
    w = inv[a] + inv[b]
    over = (depth > 0.0) & (w > 0.0)
    parent = list(range(len(inv)))

    def find(i):
        while parent[i] != i:
            i = parent[i]
        return i
    for k in np.flatnonzero(over & (inv[a] > 0.0) & (inv[b] > 0.0)):
        ra, rb = find(a[k]), find(b[k])
        parent[max(ra, rb)] = min(ra, rb)
    moving = np.where(inv[a] > 0.0, a, b)  # the manifold's moving body (either, when both move)
    bodies = Counter(find(i) for i in np.flatnonzero(inv > 0.0))
    fixed = {find(moving[k]) for k in np.flatnonzero(over & ((inv[a] == 0.0) | (inv[b] == 0.0)))}
    v = world._mode.push_speed(world._settings_store(world.solver).values)
    g = math.hypot(world._gravity[0], world._gravity[1])
    total = 0.0
    for k in np.flatnonzero(over):
        r = find(moving[k])
        p = bodies[r] - 1 + (r in fixed)
        total += 1.0 / w[k] * (0.5 * (p * v) ** 2 + g * depth[k])
    return total
