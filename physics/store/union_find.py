"""Union-find over table slots (Tarjan 1975, path halving): islands and restitution clusters.

``parent`` is an int array with ``parent[i] == i`` at a root (``np.arange(n)`` to start).
``union_roots`` makes the smaller slot the root, so a set's root is its first member in slot
order (step/islands.py relies on that to label islands in order).
"""
from __future__ import annotations

from .._jit import kernel


@kernel
def find_root(parent, i):
    """The root of i's set (halving the path on the way)."""
    while parent[i] != i:
        parent[i] = parent[parent[i]]
        i = parent[i]
    return i


@kernel
def union_roots(parent, a, b):
    """Join the sets of a and b under the smaller of their roots."""
    ra = find_root(parent, a)
    rb = find_root(parent, b)
    if ra < rb:
        parent[rb] = ra
    elif rb < ra:
        parent[ra] = rb
