"""The last finite state: saved before each step, restored when a step goes non-finite."""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel


@kernel
def save_state(B, n, X, Q, Vel, W):
    for i in range(n):
        X[i, 0] = B.x[i, 0]
        X[i, 1] = B.x[i, 1]
        Q[i] = B.q[i]
        Vel[i, 0] = B.v[i, 0]
        Vel[i, 1] = B.v[i, 1]
        W[i] = B.w[i]


@kernel
def restore_state(B, n, X, Q, Vel, W):
    for i in range(n):
        B.x[i, 0] = X[i, 0]
        B.x[i, 1] = X[i, 1]
        B.q[i] = Q[i]
        B.v[i, 0] = Vel[i, 0]
        B.v[i, 1] = Vel[i, 1]
        B.w[i] = W[i]


@kernel
def count_nonfinite(B, n, out):
    """Writes the slots whose state is NaN or infinite into ``out``; returns how many."""
    k = 0
    for i in range(n):
        s = B.x[i, 0] + B.x[i, 1] + B.q[i] + B.v[i, 0] + B.v[i, 1] + B.w[i]
        if not math.isfinite(s):
            if k < out.shape[0]:
                out[k] = i
            k += 1
    return k


class Checkpoint:
    """Preallocated copy of (x, q, v, w) for the live bodies."""

    def __init__(self):
        self._alloc(64)
        self.bad = np.zeros(16, dtype=np.int64)

    def _alloc(self, cap):
        self.X = np.zeros((cap, 2))
        self.Q = np.zeros(cap)
        self.V = np.zeros((cap, 2))
        self.W = np.zeros(cap)

    def ensure(self, n):
        if n > len(self.Q):
            self._alloc(max(n, 2 * len(self.Q)))

    def save(self, B, n):
        self.ensure(n)
        save_state(B, n, self.X, self.Q, self.V, self.W)

    def restore(self, B, n):
        restore_state(B, n, self.X, self.Q, self.V, self.W)

    def nonfinite(self, B, n) -> list[int]:
        return self.slots(count_nonfinite(B, n, self.bad))

    def slots(self, k: int) -> list[int]:
        """The first non-finite slots found by a count of ``k``."""
        return [int(s) for s in self.bad[: min(k, len(self.bad))]]
