"""The fixture table: one row per shape attached to a body (a body is a rigid set of fixtures).

A fixture is a shape plus its material (density, friction, restitution) and its collision
filter (category and mask bits, group; Box2D semantics, collision/broadphase/fixture_filter.py).
Geometry is stored relative to the body's centre of mass, like the body's own frame:
polygons, capsules, segments and chain segments keep their core vertices in the vertex pool
(a capsule or segment as a two-vertex polygon, as Box2D v3 does; ``radius`` rounds the core),
a circle keeps its centre in ``center``.  A chain segment's neighbours along its chain are
its ghost vertices (``ghost``: the vertex before a, the vertex after b) that keep the contact
one-sided and smooth.  ``world``-space copies and the AABB are refreshed every step by the
geometry stage (geometry/transform.py), which also mirrors the body's kind and awake flag so
the broad phase can run over fixtures exactly as it ran over bodies.
"""
from __future__ import annotations

import numpy as np

from .table import Table, f8, i1, i4, i8
from .table_view import view_class

u8 = np.uint64
POLYGON, CIRCLE, CAPSULE, SEGMENT, CHAIN_SEGMENT = 0, 1, 2, 3, 4
#: default filter: category bit 1, collide with every category, no group
DEFAULT_CATEGORY, ALL_BITS, DEFAULT_GROUP = 1, (1 << 64) - 1, 0

FIXTURE_FIELDS = {
    "body": ((), i4),          # body slot
    "kind": ((), i1),          # the body's kind (mirrored each step for the broad phase)
    "awake": ((), i1),         # the body's awake flag (mirrored each step)
    "shape": ((), i1),         # POLYGON / CIRCLE / CAPSULE / SEGMENT / CHAIN_SEGMENT
    "radius": ((), f8),        # circle radius, capsule radius, polygon rounding (m)
    "vstart": ((), i4),        # first core vertex in the vertex pool
    "vcount": ((), i4),        # core vertex count (0 for circles, 2 for capsules and segments)
    "center": ((2,), f8),      # circle centre relative to the body's centre of mass
    "wcenter": ((2,), f8),     # the same in world coordinates
    "ghost": ((2, 2), f8),     # chain segment: vertex before a, vertex after b (relative to the com)
    "wghost": ((2, 2), f8),    # the same in world coordinates
    "density": ((), f8),       # kg/m^2
    "e": ((), f8),             # restitution
    "mu_s": ((), f8),          # static friction coefficient
    "mu_d": ((), f8),          # dynamic friction coefficient
    "category": ((), u8),      # filter: the bits this fixture is
    "mask": ((), u8),          # filter: the bits it collides with
    "group": ((), i4),         # filter: shared positive group always collides, negative never
    "sensor": ((), i1),        # 1: a sensor: reports overlaps (step/sensor_events.py), no contact, no mass
    "aabb": ((4,), f8),        # min x, min y, max x, max y (fattened by the body's margin)
    "id": ((), i8),            # stable id (handle)
}
Fixtures = view_class("Fixtures", FIXTURE_FIELDS, "fixtures")


class FixtureTable(Table):
    """The fixture rows (swap-remove, stable ids) of one world."""

    def __init__(self, cap: int = 64):
        super().__init__(FIXTURE_FIELDS, Fixtures, cap=cap)

    def of_body(self, slot: int) -> np.ndarray:
        """Fixture slots of body ``slot`` (in table order)."""
        return np.nonzero(self.arrays["body"][: self.n] == slot)[0]

    def remap_removed_body(self, removed: int, moved_from: int) -> None:
        """A body was swap-removed: the body that moved from ``moved_from`` is now at ``removed``."""
        b = self.arrays["body"][: self.n]
        b[b == moved_from] = removed
