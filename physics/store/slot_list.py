"""Index lists over a table's slots: the loops of a step that visit only some bodies.

A stage that visits the awake bodies takes a list of their slots and its length; called for
every slot (the pipeline's path, the tools), it takes ``ALL``, an empty list, and the table's
length.  One loop then serves both: ``at`` reads the list, or under ``ALL`` the position itself
(the test is the same for every iteration, so the compiled loop does not branch on it).
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel

#: every slot: ``at(ALL, k)`` is k
ALL = np.zeros(0, np.int64)


@kernel(forceinline=True)
def at(idx, k):
    """The k-th listed slot: ``idx[k]``, or k under ``ALL`` (an empty list)."""
    return idx[k] if idx.shape[0] else k
