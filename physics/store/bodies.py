"""The body table: one row per rigid body.

Positions are stored at the centre of mass (``x``) because that is where the
equations of motion live; ``com`` (body coordinates) converts to and from the
body origin that users see.  Polygon vertices live in the vertex pool
(store/vertices.py), relative to the centre of mass for the same reason.
"""
from __future__ import annotations

from .fixtures import CIRCLE, POLYGON
from .table import f8, i1, i4, i8
from .table_view import view_class

DYNAMIC, STATIC, KINEMATIC = 0, 1, 2
KINDS = {"dynamic": DYNAMIC, "static": STATIC, "kinematic": KINEMATIC}
KIND_NAMES = {v: k for k, v in KINDS.items()}
__all__ = ["BODY_FIELDS", "Bodies", "CIRCLE", "DYNAMIC", "KINDS", "KIND_NAMES", "KINEMATIC", "POLYGON", "STATIC"]


# name: (per-entry shape, dtype)
BODY_FIELDS = {
    "x": ((2,), f8),        # centre of mass, world
    "q": ((), f8),          # angle (rad)
    "v": ((2,), f8),        # velocity of the centre of mass
    "w": ((), f8),          # angular velocity (rad/s, CCW positive)
    "m": ((), f8),          # mass (computed from density even for static bodies)
    "inertia": ((), f8),    # moment of inertia about the centre of mass
    "inv_m": ((), f8),      # 0 for static and kinematic bodies
    "inv_i": ((), f8),
    "density": ((), f8),  # first fixture: kg/m^2
    "kind": ((), i1),       # DYNAMIC / STATIC / KINEMATIC
    "e": ((), f8),  # first fixture: restitution
    "mu_s": ((), f8),  # first fixture: static friction coefficient
    "mu_d": ((), f8),  # first fixture: dynamic friction coefficient
    "shape": ((), i1),  # first fixture: POLYGON / CIRCLE
    "radius": ((), f8),  # first fixture: circle radius (0 for polygons)
    "vstart": ((), i4),  # first fixture: first vertex in the pool (polygons)
    "vcount": ((), i4),  # first fixture: vertex count (0 for circles)
    "com": ((2,), f8),      # centre of mass in body coordinates (origin -> com)
    "bound_r": ((), f8),    # radius of the bounding circle of all fixtures about the centre of mass
    "aabb": ((4,), f8),     # union of the fixtures' AABBs (fattened by the speculative margin)
    "awake": ((), i1),      # 1 awake, 0 asleep
    "sleep_t": ((), f8),    # time spent below the sleep velocity thresholds
    "island": ((), i4),     # island label while asleep (-1 awake)
    "f": ((2,), f8),        # user force accumulator, cleared every step
    "tau": ((), f8),        # user torque accumulator
    "id": ((), i8),         # stable id (handle)
}
Bodies = view_class("Bodies", BODY_FIELDS, "bodies")
