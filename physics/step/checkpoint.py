"""The last finite state: saved before each step, restored when a step goes non-finite.

A step is refused when any component of a body's state is NaN or infinite, and also when
every component is finite but an energy is not (issue 20: 48 fuzzed runs whose kinetic
energy overflowed to inf at finite speeds of ~1e154 m/s passed a check of the state alone).
Components are checked one by one: their sum overflows for a finite body at (1e308, 1e308).
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel
from ..store import DYNAMIC
from ..store.slot_list import ALL, at

STATE, ENERGY = 0, 1  # why a step is refused: a non-finite state, or a finite state whose energy is not


@kernel(entry=True)
def save_state(B, idx, m, X, Q, Vel, W):
    """The state of the ``m`` bodies listed in ``idx`` (store/slot_list.py) into X, Q, Vel, W."""
    for k in range(m):
        i = at(idx, k)
        X[i, 0] = B.x[i, 0]
        X[i, 1] = B.x[i, 1]
        Q[i] = B.q[i]
        Vel[i, 0] = B.v[i, 0]
        Vel[i, 1] = B.v[i, 1]
        W[i] = B.w[i]


@kernel(entry=True)
def restore_state(B, idx, m, X, Q, Vel, W):
    for k in range(m):
        i = at(idx, k)
        B.x[i, 0] = X[i, 0]
        B.x[i, 1] = X[i, 1]
        B.q[i] = Q[i]
        B.v[i, 0] = Vel[i, 0]
        B.v[i, 1] = Vel[i, 1]
        B.w[i] = W[i]


@kernel
def finite_state(B, i):
    """Each component of body i's state is finite."""
    return (math.isfinite(B.x[i, 0]) and math.isfinite(B.x[i, 1]) and math.isfinite(B.q[i])
            and math.isfinite(B.v[i, 0]) and math.isfinite(B.v[i, 1]) and math.isfinite(B.w[i]))


@kernel
def spring_energy(B, S, s):
    """Elastic energy 1/2 k (|d| - l0)^2 of spring s (J); inf when it overflows."""
    a = S.a[s]
    b = S.b[s]
    ca = math.cos(B.q[a])
    sa = math.sin(B.q[a])
    px = B.x[a, 0] + ca * S.la[s, 0] - sa * S.la[s, 1]
    py = B.x[a, 1] + sa * S.la[s, 0] + ca * S.la[s, 1]
    if b >= 0:
        cb = math.cos(B.q[b])
        sb = math.sin(B.q[b])
        qx = B.x[b, 0] + cb * S.lb[s, 0] - sb * S.lb[s, 1]
        qy = B.x[b, 1] + sb * S.lb[s, 0] + cb * S.lb[s, 1]
    else:
        qx = S.lb[s, 0]
        qy = S.lb[s, 1]
    stretch = math.hypot(px - qx, py - qy) - S.rest[s]
    return 0.5 * S.k[s] * stretch * stretch


@kernel(entry=True)
def count_nonfinite(B, idx, m, S, ns, out, why):
    """Writes the slots whose state is NaN or infinite into ``out``; returns how many.  Checks
    the ``m`` bodies listed in ``idx`` (store/slot_list.py: the step's rows, which are all a step
    changes) and the ``ns`` springs.

    When every state is finite but the kinetic energy (a body's or the total, as
    measures.kinetic_energy sums it) or the springs' elastic energy is not, ``why[0]`` is
    ENERGY and ``out[0]`` the body with the largest kinetic energy, or the overflowing
    spring's first body; otherwise ``why[0]`` is STATE."""
    k = 0
    total = 0.0
    worst = -1
    top = -1.0
    why[0] = STATE
    for j in range(m):
        i = at(idx, j)
        if not finite_state(B, i):
            if k < out.shape[0]:
                out[k] = i
            k += 1
            continue
        if B.kind[i] != DYNAMIC:
            continue
        e = 0.5 * (B.m[i] * (B.v[i, 0] * B.v[i, 0] + B.v[i, 1] * B.v[i, 1]) + B.inertia[i] * B.w[i] * B.w[i])
        total += e
        if not e <= top:
            top = e
            worst = i
    if k > 0:
        return k
    why[0] = ENERGY
    if not math.isfinite(total) and worst >= 0:
        out[0] = worst
        return 1
    elastic = 0.0
    for s in range(ns):
        elastic += spring_energy(B, S, s)
        if not math.isfinite(elastic):
            out[0] = S.a[s]
            return 1
    why[0] = STATE
    return 0


class Checkpoint:
    """Preallocated copy of (x, q, v, w) for the live bodies: all of them (``save``), or only the
    rows a one-call step listed (step/active.py: the bodies it can change), which ``restore``
    then puts back after ``listed`` said how many."""

    def __init__(self):
        self._alloc(64)
        self.bad = np.zeros(16, dtype=np.int64)
        self.why = np.zeros(1, dtype=np.int64)
        self.nrows = -1  # -1: the copy holds every body

    def _alloc(self, cap):
        self.X = np.zeros((cap, 2))
        self.Q = np.zeros(cap)
        self.V = np.zeros((cap, 2))
        self.W = np.zeros(cap)
        self.cluster = np.zeros((3, cap), dtype=np.int64)  # scratch: the push-out allowance's clusters (push_out.py)
        self.rows = np.zeros(cap, dtype=np.int64)  # the step's rows (step/active.py)
        self.mark = np.zeros(cap, dtype=np.int64)  # their dedup stamps

    def ensure(self, n):
        if n > len(self.Q):
            self._alloc(max(n, 2 * len(self.Q)))

    def save(self, B, n):
        self.ensure(n)
        self.nrows = -1
        save_state(B, ALL, n, self.X, self.Q, self.V, self.W)

    def listed(self, nrows: int) -> None:
        """The copy holds only ``rows[:nrows]`` (a one-call step saved those)."""
        self.nrows = nrows

    def restore(self, B, n):
        if self.nrows < 0:
            restore_state(B, ALL, n, self.X, self.Q, self.V, self.W)
        else:
            restore_state(B, self.rows, self.nrows, self.X, self.Q, self.V, self.W)

    def nonfinite(self, B, n, S, ns) -> list[int]:
        """The first slots whose state (or energy: ``self.why``) is not finite now."""
        return self.slots(count_nonfinite(B, ALL, n, S, ns, self.bad, self.why))

    def slots(self, k: int) -> list[int]:
        """The first non-finite slots found by a count of ``k``."""
        return [int(s) for s in self.bad[: min(k, len(self.bad))]]

    @property
    def energy(self) -> bool:
        """The last check refused finite states for their energy."""
        return int(self.why[0]) == ENERGY
