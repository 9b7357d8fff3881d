"""Structure-of-arrays state: bodies, the vertex pool, springs, contacts.

``Store`` bundles the tables of one world; solver modes and pipeline stages
receive it (and the step context) instead of the world object.
"""
from __future__ import annotations

from .bodies import BODY_FIELDS, CIRCLE, DYNAMIC, KIND_NAMES, KINDS, KINEMATIC, POLYGON, STATIC, Bodies
from .contacts import CARRIED, CONTACT_FIELDS, MAX_POINTS, ContactBuffer, Contacts
from .springs import SPRING_FIELDS, Springs
from .table import Table, allocate, f8, grown, i1, i4, i8
from .vertices import VERT_FIELDS, VertexPool, Verts

__all__ = ["BODY_FIELDS", "CIRCLE", "DYNAMIC", "KIND_NAMES", "KINDS", "KINEMATIC", "POLYGON", "STATIC", "Bodies",
           "CARRIED", "CONTACT_FIELDS", "MAX_POINTS", "ContactBuffer", "Contacts", "SPRING_FIELDS", "Springs",
           "Table", "allocate", "f8", "grown", "i1", "i4", "i8", "VERT_FIELDS", "VertexPool", "Verts", "Store"]


class Store:
    """The tables of one world: ``bodies``, ``verts``, ``springs``, ``contacts``."""

    __slots__ = ("bodies", "verts", "springs", "contacts")

    def __init__(self):
        self.bodies = Table(BODY_FIELDS, Bodies, cap=64)
        self.springs = Table(SPRING_FIELDS, Springs, cap=16)
        self.verts = VertexPool()
        self.contacts = ContactBuffer()
