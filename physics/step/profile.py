"""Where the last step's time went, stage by stage (like Box2D's b2Profile).

The pipeline stamps ``time.perf_counter`` at each stage boundary (about 60 ns a
stamp); the step driver stamps a cycle counter instead (clock.py) and the stages get their
shares of the call's wall time.  ``World.profile`` reads the last step's seconds per stage.
"""
from __future__ import annotations

import time

#: the stages in the order they run
STAGES = ("begin", "broadphase", "narrowphase", "solve", "islands", "finish")


class StepProfile:
    """Seconds per stage of the last full step, and its total (``step``)."""

    __slots__ = ("_t", "_times", "_stamps", "_wall")

    def __init__(self):
        self._times = {name: 0.0 for name in STAGES + ("step",)}
        self._t = 0.0
        self._stamps = None

    @property
    def times(self) -> dict:
        """Seconds per stage (and ``step``), from the driver's stamps when it ran the step."""
        if self._stamps is not None:
            T, wall = self._stamps, self._wall
            self._stamps = None
            total = T[len(STAGES)] - T[0]
            scale = wall / total if total > 0 else 0.0
            for i, name in enumerate(STAGES):
                self._times[name] = float(T[i + 1] - T[i]) * scale
            self._times["step"] = wall
        return self._times

    def defer(self, stamps, wall: float) -> None:
        """The step driver's cycle stamps (the start, then after each stage) and the call's wall
        time: the stages' seconds are the stamps' shares of it (clock.py), worked out when read."""
        self._stamps = stamps
        self._wall = wall

    def start(self) -> None:
        self._stamps = None  # a driver's step before this one: its stamps are not worked out
        for k in self._times:
            self._times[k] = 0.0
        self._t = time.perf_counter()

    def stamp(self, stage: str) -> None:
        """The time since the previous stamp is ``stage``'s."""
        t = time.perf_counter()
        self._times[stage] = t - self._t
        self._t = t

    def finish(self) -> None:
        self._times["step"] = sum(self._times[k] for k in STAGES)

    def as_dict(self) -> dict:
        return dict(self.times)
