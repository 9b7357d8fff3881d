"""``soft_step``'s ``solver_layout`` "coloured": the per-step colouring and the scratch it needs.

Each step, after the narrow phase, the step kernel (coloured.py) first colours the manifolds
(constraints/colouring.py; the colours live in the contact table, carried from step to step);
when they need more slots than the blocks hold it returns before changing anything, and the
blocks grow (doubling) for a second call.  Scratch is reused.
"""
from __future__ import annotations

import numpy as np

from ...constraints.colouring import COLOURS, LANES
from ...constraints.contact_wide import BLOCK_SIZE
from .coloured import soft_step_coloured

LAYOUTS = ("rows", "coloured")


class ColouredScratch:
    def __init__(self):
        self.force_overflow = False  # every manifold alone in its block: the row solve's order (tests)
        self.used = np.zeros(64, np.uint64)
        self.order = np.zeros(64 * LANES, np.int32)
        self.bstart = np.zeros(COLOURS + 1, np.int64)
        self._wide(64 * LANES)

    def _wide(self, slots: int) -> None:
        self.W = np.zeros(slots // LANES * BLOCK_SIZE)
        self.GA = np.zeros(slots, np.uint64)
        self.GB = np.zeros(slots, np.uint64)

    def ensure(self, store) -> None:
        """The colouring's scratch large enough for this step's bodies and manifolds."""
        n = store.bodies.n
        nc = store.contacts.n
        if n > len(self.used):
            self.used = np.zeros(2 * n, np.uint64)
        # at most one block per manifold (overflow) plus one partial block per colour
        need = nc * LANES + COLOURS * LANES
        if need > len(self.order):
            self.order = np.zeros(2 * need, np.int32)

    def step(self, ctx, par, store, R, SB, J, JW, JS) -> int:
        """The step kernel (it colours first); the number of joints that broke."""
        self.ensure(store)
        while True:
            out = soft_step_coloured(ctx.array, par.array, store.bodies.view, store.contacts.cur,
                                     store.springs.view, R, SB, J, JW, JS, self.used, self.order,
                                     self.bstart, self.force_overflow, self.W, self.GA, self.GB)
            if out >= 0:
                return out
            self._wide(2 * -out)  # more slots than the blocks hold: nothing was done yet
