"""The narrow phase's own bound: how many contact rows one step may allocate.

Each broad-phase pair becomes at most one row of the two contact tables (this step's and the
last one's, about 2 x 300 bytes a row with the solvers' per-point scratch on top).  The tables
grow by doubling; the doubling is capped at the bound, so a step never holds more than
``limit`` rows (world.max_pairs, default 1,000,000) even when it needs 0.6 x the bound, and a
step that would need more is refused with a clear error instead of allocating (issue 20,
item 4: memory bounded).  The broad phase refuses more pairs than the bound first
(broadphase/limit.py); this check keeps the narrow phase safe on its own (e.g. for pairs
handed to ``collide`` directly).
"""
from __future__ import annotations

from ...errors import SimulationError


def check_rows(need: int, limit: int) -> None:
    """SimulationError (stage 'collide') when ``need`` contact rows exceed ``limit``."""
    if need > limit:
        raise SimulationError(
            f"the narrow phase needs {need:,} contact rows, more than the bound of {limit:,} "
            "(world.max_pairs bounds the contact rows too); the step was refused before allocating: "
            "spread the bodies apart or raise world.max_pairs", stage="collide")

