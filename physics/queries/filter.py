"""The query filter: a query is a fixture-like (category, mask) pair (Box2D v3's b2QueryFilter).

Sensor fixtures are never seen by queries, as in Box2D v3.1: a sensor is a zone for events,
not a surface, so a game's ray (a lidar, a line of sight) passes through a trigger volume
(world.sensor_overlaps() answers what is inside one)."""
from __future__ import annotations

from .._jit import kernel


@kernel(forceinline=True)
def accepts(F, f, category, mask):
    """Does fixture f pass a query of ``category``/``mask`` (each side's category in the other's
    mask, and f not a sensor)?"""
    return F.sensor[f] == 0 and (F.category[f] & mask) != 0 and (F.mask[f] & category) != 0
