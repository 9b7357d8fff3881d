"""The fixture filter for a world with sensors: the same pairs as fixture_filter.filter_pairs,
with the pairs of a sensor moved out of the contact pairs into pairs of their own.

A pair with exactly one sensor becomes (sensor slot, visitor slot) in ``spairs``; a pair of
two sensors is dropped (sensors do not detect sensors, as in Box2D v3).  The collision filter
and the joints apply to sensors exactly as to contacts.  A world without sensors never runs
this (the pipeline calls filter_pairs), so it pays nothing for it.
"""
from __future__ import annotations

from ..._jit import kernel
from .fixture_filter import may_collide


@kernel(entry=True)
def split_sensor_pairs(F, pairs, npairs, keys, spairs):
    """Compact ``pairs[:npairs]`` to the contact pairs and write the sensor pairs to ``spairs``
    (room for ``npairs`` rows); returns (contact pairs, sensor pairs)."""
    k = 0
    ks = 0
    for p in range(npairs):
        i = pairs[p, 0]
        j = pairs[p, 1]
        if not may_collide(F, keys, i, j):
            continue
        si = F.sensor[i] != 0
        sj = F.sensor[j] != 0
        if si or sj:
            if not (si and sj):
                spairs[ks, 0] = i if si else j
                spairs[ks, 1] = j if si else i
                ks += 1
            continue
        pairs[k, 0] = i
        pairs[k, 1] = j
        k += 1
    return k, ks
