"""``soft_step``'s ``solver_layout`` "coloured": the per-step colouring and the scratch it needs.

Each step, after the narrow phase, the step kernel (coloured.py) first colours the manifolds
(constraints/colouring.py; the colours live in the contact table, carried from step to step);
when they need more slots than the blocks hold it returns before changing anything, and the
blocks grow (doubling) for a second call.  Scratch is reused.

The blocks are float32, as Box2D v3's (b2FloatW): a pass streams every block once, and at
float64 a large pile's blocks outgrow the cache (suite washer and large_pyramid 11-12 % faster
a step in float32, docs/benchmarks.md).  The arithmetic stays in float64 where a body's state
enters it.  ``force`` holds colouring.py's test flags (tests/test_coloured_solve.py).
"""
from __future__ import annotations

import numpy as np

from ...constraints.colouring import BSTART, COLOURS, LANES
from ...constraints.contact_prepare import T_SIZE
from ...constraints.contact_wide import BLOCK_SIZE, V_SIZE
from .coloured import soft_step_coloured

LAYOUTS = ("coloured",)  # soft_step's solver_layout choices (mode.py)


class ColouredScratch:
    def __init__(self):
        # colouring.py's test flags (FORCE_OVERFLOW, IN_TURN, VIA_ROWS); an array, so that the
        # one-call driver's pack sees a change made after it was built
        self.force = np.zeros(1, np.int64)
        self.used = np.zeros(64, np.uint64)
        self.order = np.zeros(64 * LANES, np.int32)
        self.bstart = np.zeros(BSTART, np.int64)
        self._wide(64 * LANES)

    def _wide(self, slots: int) -> None:
        self.W = np.zeros(slots // LANES * BLOCK_SIZE, np.float32)
        # the lanes' new velocities (float64: contact_wide.py), then the preparation's staging
        # (contact_prepare.py)
        self.WV = np.zeros(slots // LANES * (V_SIZE + T_SIZE))
        self.GA = np.zeros(slots, np.uint64)
        self.GB = np.zeros(slots, np.uint64)

    def ensure(self, store, rows: int | None = None) -> None:
        """The colouring's scratch large enough for this step's bodies and ``rows`` manifolds (the
        contact table's count; the one-call driver passes its capacity, which bounds every step
        until the pack is rebuilt)."""
        n = store.bodies.n
        nc = store.contacts.n if rows is None else rows
        if n > len(self.used):
            self.used = np.zeros(2 * n, np.uint64)
        # every colour (the overflow one too) padded to whole blocks: at most LANES - 1 padding each
        need = nc + COLOURS * LANES
        if need > len(self.order):
            self.order = np.zeros(2 * need, np.int32)

    def grow(self, slots: int) -> None:
        """Blocks for at least ``slots`` slots (doubling), never fewer than now: the scratch is the
        mode's, shared by every world of the process, and a pack may hold an older, shorter one."""
        self._wide(max(2 * slots, len(self.GA)))

    def pack_fields(self) -> tuple:
        """The scratch the one-call driver's pack holds (step/soft_driver.py: ``wide``)."""
        return self.used, self.order, self.bstart, self.force, self.W, self.WV, self.GA, self.GB

    def step(self, ctx, par, store, R, SB, J, JW, JS) -> int:
        """The step kernel (it colours first); the number of joints that broke."""
        self.ensure(store)
        while True:
            out = soft_step_coloured(ctx.array, par.array, store.bodies.view, store.contacts.cur,
                                     store.springs.view, R, SB, J, JW, JS, self.used, self.order,
                                     self.bstart, self.force[0], self.W, self.WV, self.GA, self.GB)
            if out >= 0:
                return out
            self.grow(-out)  # more slots than the blocks hold: nothing was done yet
