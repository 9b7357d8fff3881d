"""What the stats window plots: ring buffers of per-frame samples, and the sampler that fills them."""
from __future__ import annotations

import math
import time

import numpy as np


class Stats:
    """Ring buffers of per-frame samples for the plots (the last ``cap`` frames)."""

    KEYS = ("t", "step_ms", "ke", "pe", "p", "pen", "contacts")

    def __init__(self, cap: int = 600):
        self.cap = cap
        self.data = {k: np.zeros(cap) for k in self.KEYS}
        self.n = 0
        self.i = 0

    def add(self, **values):
        for k in self.KEYS:
            self.data[k][self.i] = values.get(k, 0.0)
        self.i = (self.i + 1) % self.cap
        self.n = min(self.n + 1, self.cap)

    def _order(self):
        if self.n < self.cap:
            return np.arange(self.n)
        return (np.arange(self.cap) + self.i) % self.cap

    def arrays(self):
        """(sample times in seconds of time.monotonic, number of samples), oldest first."""
        o = self._order()
        return self.data["t"][o], len(o)

    def get(self, k):
        """Series ``k`` (one of KEYS), oldest first."""
        return self.data[k][self._order()]

    def clear(self):
        self.n = self.i = 0


def deepest(depths) -> float:
    """The largest of ``world.contact_depths()`` (m), 0 when nothing touches."""
    return float(depths.max()) if len(depths) else 0.0


class StatsSampler:
    """One sample per frame: step time, energies, momentum; the contact count and deepest
    penetration (``world.contact_depths()``, numpy) and ``world.info()`` every sixth frame.
    (Reading them through ``world.contacts()``, a Python object per contact, took about 30 ms
    at 1000 bodies and made every sixth frame a hitch.)"""

    def __init__(self):
        self.stats = Stats()
        self.info: dict = {}
        self.last_contacts = (0, 0.0)    # (count, deepest penetration in m)
        self.steps = 0                   # world.steps when the counts were read

    def sample(self, world, phys_ms: float, steps: int, frame_no: int) -> None:
        if frame_no % 6 == 0 or not self.stats.n:
            d = world.contact_depths()     # numpy: no Python object per contact
            self.last_contacts = (len(d), deepest(d))
            self.info = world.info()
            self.steps = world.steps
        p = world.linear_momentum()
        self.stats.add(t=time.monotonic(), step_ms=phys_ms / max(steps, 1), ke=world.kinetic_energy(),
                       pe=world.potential_energy(), p=math.hypot(*p), pen=max(0.0, self.last_contacts[1]),
                       contacts=self.last_contacts[0])

    def counts(self) -> dict:
        """The counts the stats window shows, from the last read.  The core tests no pair of two
        sleeping bodies (nor a sleeping body against a static one), so ``touching`` (as
        ``len(world.contacts())``) and ``pairs`` (the narrow phase's rows, ``world.info()['contacts']``,
        touching or a speculative margin apart) count only pairs with an awake body.  While every
        body sleeps no step runs, and both hold the last step's figures."""
        info = self.info
        dynamic, awake = info.get("dynamic", 0), info.get("awake", 0)
        return {"bodies": info.get("bodies", 0), "awake": awake, "asleep": dynamic - awake,
                "springs": info.get("springs", 0), "touching": self.last_contacts[0],
                "pairs": info.get("contacts", 0), "steps": self.steps,
                "all_asleep": bool(info.get("sleeping")) and dynamic > 0 and awake == 0}

    def clear(self):
        self.stats.clear()


class FrameTimes:
    """The split of one frame (physics, upload, draw, ui, frame; ms): the last frame and a
    running average (weight 0.1 per frame), and frames per second.  ``last`` also holds the
    finer parts the frame benchmark reports (``swap``, ``plot``: the Plot tab's share of ``ui``)."""

    KEYS = ("physics", "upload", "draw", "ui", "frame")

    def __init__(self):
        self.avg = {k: 0.0 for k in self.KEYS}
        self.last: dict | None = None
        self.fps = 0.0

    def record(self, real_dt: float, **ms) -> None:
        a = 0.1
        for k in self.KEYS:
            self.avg[k] = (1 - a) * self.avg[k] + a * ms[k]
        self.last = dict(ms)
        if real_dt > 0:
            self.fps = 0.9 * self.fps + 0.1 / real_dt if self.fps else 1.0 / real_dt

    def add_swap(self, flip_ms: float) -> None:
        """llvmpipe rasterises when the frame is swapped: count the swap as drawing."""
        if self.last:
            self.last["swap"] = flip_ms
            self.last["draw"] += flip_ms
            self.last["frame"] += flip_ms
            self.avg["draw"] += 0.1 * flip_ms
            self.avg["frame"] += 0.1 * flip_ms
