"""``soft_step``'s ``solver_layout`` "coloured": the per-step colouring and the scratch it needs.

Each step, after the narrow phase, the manifolds are coloured (constraints/colouring.py) from
Python, so the blocks' scratch can be sized to this step's slot count before the step kernel
(coloured.py) runs; arrays grow by doubling and are reused.
"""
from __future__ import annotations

import numpy as np

from ...constraints.colouring import COLOURS, LANES, colour_contacts
from ...constraints.contact_wide import BLOCK_SIZE
from .coloured import soft_step_coloured

LAYOUTS = ("rows", "coloured")


class ColouredScratch:
    def __init__(self):
        self.force_overflow = False  # every manifold alone in its block: the row solve's order (tests)
        self.used = np.zeros(64, np.uint64)
        self.colour = np.zeros(64, np.int32)
        self.order = np.zeros(64 * LANES, np.int32)
        self.bstart = np.zeros(COLOURS + 1, np.int64)
        self._wide(64 * LANES)

    def _wide(self, slots: int) -> None:
        self.W = np.zeros(slots // LANES * BLOCK_SIZE)
        self.GA = np.zeros(slots, np.uint64)
        self.GB = np.zeros(slots, np.uint64)

    def colour_step(self, store) -> int:
        """Colour this step's manifolds; the number of slots they take."""
        n = store.bodies.n
        nc = store.contacts.n
        if n > len(self.used):
            self.used = np.zeros(2 * n, np.uint64)
        # at most one block per manifold (overflow) plus one partial block per colour
        need = nc * LANES + COLOURS * LANES
        if nc > len(self.colour) or need > len(self.order):
            self.colour = np.zeros(2 * nc, np.int32)
            self.order = np.zeros(2 * need, np.int32)
        B = store.bodies.view
        C = store.contacts.cur
        slots = colour_contacts(C.a, C.b, nc, B.inv_m, B.inv_i, n, self.used, self.colour, self.order,
                                self.bstart, self.force_overflow)
        if slots > len(self.GA):
            self._wide(2 * slots)
        return slots

    def step(self, ctx, par, store, R, SB, J, JW, JS) -> int:
        """Colour, then run the step kernel; the number of joints that broke."""
        slots = self.colour_step(store)
        return soft_step_coloured(ctx.array, par.array, store.bodies.view, store.contacts.cur,
                                  store.springs.view, R, SB, J, JW, JS, self.order, slots, self.bstart,
                                  self.W, self.GA, self.GB)
