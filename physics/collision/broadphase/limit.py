"""The bound on what one step may allocate for contacts: the number of candidate pairs.

Each pair the broad phase reports becomes at most one contact row, and a row costs
about 1 kB over the contact tables (this step's and the last) and a solver's scratch.
The body count does not bound pairs: 6,000 coincident circles (a 270 kB scene file) are
18 million pairs, more than 6 GB at the first step (issue 20).  ``find_pairs`` counts the
pairs before it allocates for them and refuses a step that would need more than the
world's ``max_pairs``.
"""
from __future__ import annotations

from ...errors import SimulationError

#: default bound on candidate pairs per step (about 1 GB of contact rows at the most)
MAX_PAIRS = 1_000_000
BYTES_PER_PAIR = 1000  # rough cost of one pair's contact rows (both tables and solver scratch)


def check_pairs(count: int, limit: int, n: int) -> None:
    """SimulationError (stage 'broadphase') when ``count`` pairs of ``n`` fixtures exceed ``limit``."""
    if count > limit:
        raise SimulationError(
            f"the broad phase found {count:,} overlapping pairs among {n:,} fixtures, more than the "
            f"world's max_pairs = {limit:,} (about {count * BYTES_PER_PAIR / 1e9:.1f} GB of contact rows); "
            "the step was refused: spread the bodies apart (many bodies piled in one place) or raise "
            "world.max_pairs", stage="broadphase")
