"""Which overlapping fixture pairs may collide: not two fixtures of one body, the collision
filter, and not two bodies a joint joins (unless the joint asks for ``collide_connected``).

The filter has Box2D's semantics (b2ShouldShapesCollide): a shared non-zero ``group``
decides alone (positive: always collide, negative: never); otherwise two fixtures collide
when each one's category bits meet the other's mask, ``(ca & mb) != 0 and (cb & ma) != 0``.

The joints' keys ``(min body slot << 32) | max body slot`` are kept sorted (constraints/
joints/work.py) and each pair's bodies are looked up by bisection.
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel
from ..argsort import first_at_least
from ...store.flat import fixtures_view
from ..reach import may_touch


@kernel(forceinline=True)
def should_collide(F, i, j):
    """Box2D's filter rule for fixtures i and j (module docstring)."""
    gi = F.group[i]
    if gi == F.group[j] and gi != 0:
        return gi > 0
    return (F.category[i] & F.mask[j]) != 0 and (F.category[j] & F.mask[i]) != 0


@kernel(forceinline=True)
def _joined(keys, a, b):
    """Is the body pair (a, b) in the sorted joint keys?"""
    m = keys.shape[0]
    if m == 0:
        return False
    key = np.int64(min(a, b)) * 4294967296 + np.int64(max(a, b))
    lo = first_at_least(keys, m, key)
    return lo < m and keys[lo] == key


@kernel(forceinline=True)
def may_collide(F, keys, i, j):
    """Fixtures i and j are on different bodies, their filters let them meet and no joint
    between their bodies turns collision off."""
    a = F.body[i]
    b = F.body[j]
    return a != b and should_collide(F, i, j) and not _joined(keys, a, b)


@kernel(entry=True)
def filter_pairs(F, pairs, npairs, keys):
    """Compact the fixture pairs ``pairs[:npairs]`` to those that may collide; returns the count."""
    k = 0
    for p in range(npairs):
        i = pairs[p, 0]
        j = pairs[p, 1]
        if not may_collide(F, keys, i, j):
            continue
        pairs[k, 0] = i
        pairs[k, 1] = j
        k += 1
    return k


@kernel
def filter_reachable(B, F, pairs, npairs, keys, dt, spec):
    """``filter_pairs``, keeping only the pairs whose bodies can also meet within the step
    (reach.may_touch, the narrow phase's first test, symmetric in the two bodies): the narrow
    phase would drop the others unseen, so its rows are the same, and the many boxes a fast
    body's fat box overlaps but cannot reach are neither sorted nor handed on."""
    k = 0
    for p in range(npairs):
        i = pairs[p, 0]
        j = pairs[p, 1]
        if not may_collide(F, keys, i, j) or not may_touch(B, F.body[i], F.body[j], dt, spec):
            continue
        pairs[k, 0] = i
        pairs[k, 1] = j
        k += 1
    return k


@kernel(entry=True, runtime=True)
def filter_pairs_flat(FF, FI, ghost, wghost, pairs, npairs, keys):
    """``filter_pairs`` over the fixture table's flat arrays (store/flat.py)."""
    return filter_pairs(fixtures_view(FF, FI, ghost, wghost), pairs, npairs, keys)
