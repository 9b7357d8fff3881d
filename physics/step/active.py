"""The bodies a step visits: the moving ones, and those the step's constraints reach.

A sleeping island is at rest and a static body never moves, so the one-call step's stages that
save, integrate, check and sum bodies visit a list of the moving slots (``act``: dynamic and
awake, or kinematic, in slot order) and the fixtures whose geometry can change (``actf``); the
sleeping bodies enter the energy guard as sums kept while they sleep (``rest``,
energy_sums.rest_sums).  Box2D v3 keeps its awake bodies in a solver set of their own the same
way (solver_set.c), so that a sleeping pile costs nothing per step.  The lists are rebuilt only
when they change: after an edit (the driver's S_GEOM) and when islands wake or fall asleep
(islands.py counts them).

After the narrow phase the step also lists its rows (``rows``): ``act`` followed, in slot order,
by the other bodies a contact, joint or spring of this step reaches.  Those are every body whose
velocity the solvers read or write (a sleeper can be pushed by an awake body's speculative
contact before it wakes: islands._wake_pushed), so the rows are what the step saves for a
refusal, checks for finiteness and copies in and out of the solver's body rows.
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from ..collision.argsort import argsort_into
from ..store import DYNAMIC, STATIC
from .energy_sums import rest_sums
from .islands import moving_slots

#: the sums of the sleeping bodies (energy_sums.SUMS slots) start in this slot of the driver's D
REST_SLOTS = 7


@kernel
def partition(B, F, n, nf, gx, gy, act, actf, sleepers, rest):
    """``act`` (moving_slots), ``actf`` (the fixtures of bodies that are not static and are awake
    or were when their geometry was last computed: geometry.transform._kept) and ``rest``, the
    guard's sums of the sleeping dynamic bodies (their slots listed in ``sleepers``).  Returns the
    lengths of ``act``, ``actf`` and ``sleepers``."""
    nact = moving_slots(B, n, act)
    k = 0
    for i in range(n):
        if B.kind[i] == DYNAMIC and B.awake[i] == 0:
            sleepers[k] = i
            k += 1
    rest_sums(B, sleepers, k, gx, gy, rest)
    nactf = 0
    for f in range(nf):
        i = F.body[f]
        if B.kind[i] != STATIC and (B.awake[i] == 1 or F.awake[f] == 1):
            actf[nactf] = f
            nactf += 1
    return nact, nactf, k


@kernel
def link_islands(B, sleepers, k, ring, key, order, tmp):
    """``ring``: for each of the ``k`` sleeping bodies listed in ``sleepers`` the next member of
    its island, a cycle per island, so that waking one visits its island only (islands.py; the
    step keeps the cycles of the islands it puts to sleep).  Built after an edit, which may have
    made or changed islands anywhere: the sleepers sorted by label (``key``, ``order``, ``tmp``
    scratch of k or more)."""
    for j in range(k):
        key[j] = B.island[sleepers[j]]
    argsort_into(key, k, order, tmp)
    start = 0
    for j in range(k):
        i = sleepers[order[j]]
        last = j + 1 == k or key[order[j + 1]] != key[order[j]]
        ring[i] = sleepers[order[start]] if last else sleepers[order[j + 1]]
        if last:
            start = j + 1


@kernel(forceinline=True)
def _add(i, rows, mark, stamp, k):
    """Body i appended to ``rows[k:]`` unless marked with ``stamp``; the new length."""
    if i < 0 or mark[i] == stamp:
        return k
    mark[i] = stamp
    rows[k] = i
    return k + 1


@kernel
def step_rows(Ca, Cb, nc, J, nj, S, ns, act, nact, rows, mark, stamp, key, order, tmp):
    """``rows`` (module doc): the ``nact`` slots of ``act``, then in slot order the other bodies of
    the ``nc`` manifolds (``Ca``, ``Cb``), the ``nj`` joints (``J``, None without) and the ``ns``
    springs (``S``); ``mark`` per-body scratch, ``stamp`` a value it holds for no body yet;
    ``key``, ``order``, ``tmp`` the sort's scratch (n long).  Returns the count."""
    for k in range(nact):
        rows[k] = act[k]
        mark[act[k]] = stamp
    k = nact
    for j in range(nc):
        k = _add(Ca[j], rows, mark, stamp, k)
        k = _add(Cb[j], rows, mark, stamp, k)
    if J is not None:
        for j in range(nj):
            k = _add(J.a[j], rows, mark, stamp, k)
            k = _add(J.b[j], rows, mark, stamp, k)
    for j in range(ns):
        k = _add(S.a[j], rows, mark, stamp, k)
        k = _add(S.b[j], rows, mark, stamp, k)
    # the others in slot order, as a loop over every body would meet them
    m = k - nact
    for j in range(m):
        key[j] = rows[nact + j]
    argsort_into(key, m, order, tmp)
    for j in range(m):
        tmp[j] = rows[nact + order[j]]
    for j in range(m):
        rows[nact + j] = tmp[j]
    return k


class Active:
    """The lists' arrays for a world of ``n`` bodies and ``nf`` fixtures (the driver's pack holds
    them: one_call.py)."""

    def __init__(self):
        self.act = self.sleepers = self.actf = None
        self.ensure(0, 0)

    def ensure(self, n: int, nf: int) -> None:
        if self.act is None or n > len(self.act) or nf > len(self.actf):
            cap, capf = max(n, 16), max(nf, 16)
            self.act = np.zeros(cap, np.int64)
            self.sleepers = np.zeros(cap, np.int64)
            self.actf = np.zeros(capf, np.int64)
            # the resting boxes' index (broadphase/resting_index.py): its scratch, keys and fixtures
            self.index = (np.zeros(capf), np.zeros(capf, np.int64), np.zeros(capf, np.int64), np.zeros(capf),
                          np.zeros(capf, np.int64))
            self.ring = np.zeros(cap, np.int64)  # the islands' member cycles (link_islands)
            # a sort's scratch over bodies (link_islands, step_rows): keys, order, merge space
            self.sort = (np.zeros(cap), np.zeros(cap, np.int64), np.zeros(cap, np.int64))

    def fields(self, rows: np.ndarray, mark: np.ndarray) -> tuple:
        """The pack's ``active`` field, with the checkpoint's ``rows`` and their ``mark``s:
        (act, actf, sleepers, rows, mark, index, ring, *sort), as the driver unpacks it."""
        return (self.act, self.actf, self.sleepers, rows, mark, self.index, self.ring, *self.sort)
