"""Islands and sleeping.

Bodies linked by touching contacts, springs or joints form an island (union-find
over the contact graph, Tarjan 1975 with path halving).  An island sleeps
when every body in it has stayed below the linear and angular speed
thresholds for ``time_to_sleep``; a sleeping body is skipped by the broad
phase against static and sleeping bodies, by the solvers and by the
integrators, so a resting pile costs almost nothing.  A sleeping island
wakes as a whole (bodies share an island label) when an awake body or a
moving kinematic body touches it, or when the user edits one of its bodies.
Joints (``JL``: per unbroken joint its bodies a, b (-1: the world) and whether
its motor is driving) join islands and carry waking across; a driving motor
keeps its bodies awake.
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from ..store import DYNAMIC, KINEMATIC
from ..store.flat import bodies_view, contacts_view, joints_view, springs_view
from ..store.joints import BROKEN, MOUSE
from ..store.slot_list import at
from ..store.union_find import find_root, union_roots

#: ``label``'s slots: the last island label given, and a count of islands woken or put to sleep
#: (the step's list of moving bodies changes with it: step/active.py)
LABEL, WOKEN = range(2)


@kernel
def _wake_island(B, n, s, label, ring):
    """Wake body s and its sleeping island; ``label[WOKEN]`` counts it.  The island's members are
    found along ``ring`` (step/active.py: each sleeper's next member, a cycle per island) or,
    without rings (an empty array: the pipeline's step), by a scan of every body."""
    label[WOKEN] += 1
    lab = B.island[s]
    if lab < 0:
        B.awake[s] = 1
        B.sleep_t[s] = 0.0
        return
    if ring.shape[0]:
        i = s
        while True:
            nxt = ring[i]
            B.awake[i] = 1
            B.sleep_t[i] = 0.0
            B.island[i] = -1
            i = nxt
            if i == s:
                return
    for i in range(n):
        if B.island[i] == lab:
            B.awake[i] = 1
            B.sleep_t[i] = 0.0
            B.island[i] = -1


@kernel
def _moving(B, i):
    return B.v[i, 0] != 0.0 or B.v[i, 1] != 0.0 or B.w[i] != 0.0


@kernel
def _wake_touched(B, n, C, nc, S, ns, slop, label, ring):
    """Wake sleeping islands touched by awake dynamic or moving kinematic bodies."""
    for k in range(nc):
        touching = C.depth[k, 0] > -slop or (C.count[k] > 1 and C.depth[k, 1] > -slop)
        if not touching:
            continue
        a = C.a[k]
        b = C.b[k]
        for side in range(2):
            s = a if side == 0 else b
            o = b if side == 0 else a
            if B.kind[s] == DYNAMIC and B.awake[s] == 0 and B.awake[o] == 1:
                if B.kind[o] == DYNAMIC or (B.kind[o] == KINEMATIC and _moving(B, o)):
                    _wake_island(B, n, s, label, ring)
    for k in range(ns):
        a = S.a[k]
        b = S.b[k]
        if b < 0:
            continue
        if B.awake[a] == 0 and B.awake[b] == 1 and B.kind[a] == DYNAMIC:
            _wake_island(B, n, a, label, ring)
        elif B.awake[b] == 0 and B.awake[a] == 1 and B.kind[b] == DYNAMIC:
            _wake_island(B, n, b, label, ring)


@kernel
def _wake_linked(B, n, a, b, label, ring):
    """Wake the sleeping side of a link between an awake and a sleeping dynamic body."""
    if b < 0:
        return
    if B.awake[a] == 0 and B.awake[b] == 1 and B.kind[a] == DYNAMIC:
        _wake_island(B, n, a, label, ring)
    elif B.awake[b] == 0 and B.awake[a] == 1 and B.kind[b] == DYNAMIC:
        _wake_island(B, n, b, label, ring)


@kernel
def _joint_links(B, n, JL, parent, label, ring):
    """Wake across joints, keep driven bodies awake, union the joined dynamic bodies."""
    for k in range(JL.shape[0]):
        a = JL[k, 0]
        b = JL[k, 1]
        _wake_linked(B, n, a, b, label, ring)
        if JL[k, 2]:
            for s in (a, b):
                if s >= 0 and B.kind[s] == DYNAMIC:
                    if B.awake[s] == 0:
                        _wake_island(B, n, s, label, ring)
                    B.sleep_t[s] = 0.0
        if b >= 0 and _both_awake(B, a, b):
            union_roots(parent, a, b)


@kernel
def _restless(B, i, lin_tol, ang_tol):
    """Too fast to sleep: the centre or the rim (|w| times the bounding radius, as Box2D v3
    measures rotation) moves faster than ``lin_tol``, or it spins faster than ``ang_tol``
    (which only matters for tiny bodies, whose rims are slow even when spinning visibly)."""
    v2 = B.v[i, 0] * B.v[i, 0] + B.v[i, 1] * B.v[i, 1]
    w = abs(B.w[i])
    return v2 > lin_tol * lin_tol or w * B.bound_r[i] > lin_tol or w > ang_tol


@kernel
def _wake_pushed(B, n, idx, k0, k1, lin_tol, ang_tol, label, ring):
    """Sleepers are put to sleep at rest, so a velocity now came from an impulse this step
    (e.g. a speculative row, not yet touching, that stopped a body thrown at the sleeper).
    Above the sleep thresholds it wakes the island; below, it is a nudge and is dropped
    (waking on every nudge would keep a settling pile from ever sleeping island by island).
    Visits the listed bodies k0..k1-1 in slot order (``idx``, store/slot_list.py): every body,
    or the step's rows that are not awake (no other sleeper has a velocity)."""
    for k in range(k0, k1):
        i = at(idx, k)
        if B.kind[i] != DYNAMIC or B.awake[i] == 1 or not _moving(B, i):
            continue
        if _restless(B, i, lin_tol, ang_tol):
            _wake_island(B, n, i, label, ring)
        else:
            B.v[i, 0] = 0.0
            B.v[i, 1] = 0.0
            B.w[i] = 0.0


@kernel(forceinline=True)
def _both_awake(B, a, b):
    """Two awake dynamic bodies: a link the islands join (a link to a sleeper woke it first)."""
    return B.kind[a] == DYNAMIC and B.kind[b] == DYNAMIC and B.awake[a] == 1 and B.awake[b] == 1


@kernel
def update_islands(ctx, B, C, S, JL, parent, min_t, label, ring, act, nact, rows, nrows):
    """One sleep update after the solver; returns the number of awake non-static bodies.

    ``JL`` the joint links (see the module doc; no rows without joints); ``parent`` and
    ``min_t`` are scratch arrays of at least n entries; ``label`` the counters of fresh island
    labels and of islands woken or put to sleep (LABEL, WOKEN); ``ring`` the islands' member
    cycles (step/active.py; kept here as islands fall asleep), or empty (none: waking scans).
    ``act``: the ``nact`` moving bodies (step/active.py: in slot order; listed again here when an
    island wakes, and by the caller after any island woke or fell asleep: ``label[WOKEN]``) or ALL
    and n; ``rows`` the step's ``nrows`` rows (act's first) or ALL and n (store/slot_list.py).
    """
    c = ctx[0]
    n = c.n
    nc = c.nc
    ns = c.ns
    dt = c.dt
    slop = c.slop
    lin_tol = c.sleep_linear
    ang_tol = c.sleep_angular
    time_to_sleep = c.time_to_sleep
    listed = act.shape[0] > 0
    woken = label[WOKEN]
    _wake_touched(B, n, C, nc, S, ns, slop, label, ring)
    _wake_pushed(B, n, rows, nact if listed else 0, nrows, lin_tol, ang_tol, label, ring)
    if listed and label[WOKEN] != woken:
        nact = moving_slots(B, n, act)
    for k in range(nact):
        i = at(act, k)
        parent[i] = i
        if B.kind[i] == DYNAMIC and B.awake[i] == 1:
            if _restless(B, i, lin_tol, ang_tol):
                B.sleep_t[i] = 0.0
            else:
                B.sleep_t[i] += dt
    for k in range(nc):
        touching = C.depth[k, 0] > -slop or (C.count[k] > 1 and C.depth[k, 1] > -slop)
        if not touching:
            continue
        a = C.a[k]
        b = C.b[k]
        ka = B.kind[a]
        kb = B.kind[b]
        if _both_awake(B, a, b):
            union_roots(parent, a, b)
        # resting on a moving kinematic body is not rest
        elif ka == KINEMATIC and _moving(B, a) and kb == DYNAMIC:
            B.sleep_t[b] = 0.0
        elif kb == KINEMATIC and _moving(B, b) and ka == DYNAMIC:
            B.sleep_t[a] = 0.0
    for k in range(ns):
        a = S.a[k]
        b = S.b[k]
        if b >= 0 and _both_awake(B, a, b):
            union_roots(parent, a, b)
    if JL.shape[0]:
        _joint_links(B, n, JL, parent, label, ring)
    return _sleep(B, act, nact, parent, min_t, label, ring, time_to_sleep)


@kernel
def _sleep(B, act, nact, parent, min_t, label, ring, time_to_sleep):
    """Put to sleep every island whose bodies all rested ``time_to_sleep``; the awake count."""
    for k in range(nact):
        min_t[at(act, k)] = np.inf
    for k in range(nact):
        i = at(act, k)
        if B.kind[i] == DYNAMIC and B.awake[i] == 1:
            r = find_root(parent, i)
            if B.sleep_t[i] < min_t[r]:
                min_t[r] = B.sleep_t[i]
    awake = 0
    for k in range(nact):
        i = at(act, k)
        if B.kind[i] == DYNAMIC and B.awake[i] == 1:
            r = find_root(parent, i)
            if min_t[r] >= time_to_sleep:
                # the root is the island's smallest slot (see union_roots), so it comes first
                if i == r:
                    label[LABEL] += 1
                    B.island[i] = label[LABEL]
                    label[WOKEN] += 1
                    if ring.shape[0]:
                        ring[i] = i  # the island's cycle, grown as its members follow
                else:
                    B.island[i] = B.island[r]
                    if ring.shape[0]:
                        ring[i] = ring[r]
                        ring[r] = i
                B.awake[i] = 0
                B.v[i, 0] = 0.0
                B.v[i, 1] = 0.0
                B.w[i] = 0.0
            else:
                awake += 1
        elif B.kind[i] == KINEMATIC and _moving(B, i):
            awake += 1
    return awake


@kernel
def moving_slots(B, n, act):
    """The slots of the bodies that can move (dynamic and awake, or kinematic), in slot order,
    into ``act``; returns how many."""
    k = 0
    for i in range(n):
        kind = B.kind[i]
        if kind == KINEMATIC or (kind == DYNAMIC and B.awake[i] == 1):
            act[k] = i
            k += 1
    return k


@kernel(entry=True, runtime=True)
def update_islands_flat(ctx, BF, BI, CF, CI, Cpt, SF, SI, JL, parent, min_t, label):
    """``update_islands`` over the body, contact and spring tables' flat arrays (store/flat.py)."""
    every = np.zeros(0, np.int64)  # store/slot_list.ALL
    n = ctx[0].n
    return update_islands(ctx, bodies_view(BF, BI), contacts_view(CF, CI, Cpt), springs_view(SF, SI), JL, parent,
                          min_t, label, every, every, n, every, n)


class Islands:
    """Scratch for the sleep update, reused every step."""

    def __init__(self):
        self.parent = np.zeros(64, dtype=np.int64)
        self.min_t = np.zeros(64)
        self.label = np.zeros(2, dtype=np.int64)  # LABEL, WOKEN
        self._no_links = np.zeros((0, 3), dtype=np.int64)
        self._links = np.zeros((16, 3), dtype=np.int64)

    def update(self, ctx, store) -> int:
        n = store.bodies.n
        if n > len(self.parent):
            self.parent = np.zeros(2 * n, dtype=np.int64)
            self.min_t = np.zeros(2 * n)
        links = self._no_links
        if store.joints.n:
            if store.joints.n > len(self._links):
                self._links = np.zeros((2 * store.joints.n, 3), dtype=np.int64)
            links = self._links[:joint_links_flat(*store.joints.arrays.flat, store.joints.n, self._links)]
        return update_islands_flat(ctx.array, *store.bodies.arrays.flat, *store.contacts.cur_cols.flat,
                                   *store.springs.arrays.flat, links, self.parent, self.min_t, self.label)


@kernel(entry=True, runtime=True)
def joint_links_flat(JF, JI, nj, out):
    """``joint_links`` over the joint table's flat arrays."""
    return joint_links(joints_view(JF, JI), nj, out)


@kernel
def joint_links(J, nj, out):
    """(a, b, driving) per unbroken joint, into ``out``: the rows ``update_islands`` reads;
    returns the row count."""
    k = 0
    for j in range(nj):
        if J.flags[j] & BROKEN:
            continue
        out[k, 0] = J.a[j]
        out[k, 1] = J.b[j]
        out[k, 2] = J.max_motor[j] > 0.0 and J.motor_speed[j] != 0.0 and J.kind[j] != MOUSE
        k += 1
    return k
