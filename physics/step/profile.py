"""Where the last step's time went, stage by stage (like Box2D's b2Profile).

The pipeline stamps ``time.perf_counter`` at each stage boundary (about 60 ns a
stamp); ``World.profile`` reads the last step's seconds per stage.
"""
from __future__ import annotations

import time

#: the stages in the order they run
STAGES = ("begin", "broadphase", "narrowphase", "solve", "islands", "finish")


class StepProfile:
    """Seconds per stage of the last full step, and its total (``step``)."""

    __slots__ = ("_t", "times")

    def __init__(self):
        self.times = {name: 0.0 for name in STAGES + ("step",)}
        self._t = 0.0

    def start(self) -> None:
        for k in self.times:
            self.times[k] = 0.0
        self._t = time.perf_counter()

    def stamp(self, stage: str) -> None:
        """The time since the previous stamp is ``stage``'s."""
        t = time.perf_counter()
        self.times[stage] = t - self._t
        self._t = t

    def finish(self) -> None:
        self.times["step"] = sum(self.times[k] for k in STAGES)

    def as_dict(self) -> dict:
        return dict(self.times)
