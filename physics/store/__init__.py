"""Structure-of-arrays state: bodies, the vertex pool, springs, joints, contacts.

``Store`` bundles the tables of one world; solver modes and pipeline stages
receive it (and the step context) instead of the world object.
"""
from __future__ import annotations

from .bodies import BODY_FIELDS, CIRCLE, DYNAMIC, KIND_NAMES, KINDS, KINEMATIC, POLYGON, STATIC, Bodies
from .fixtures import FIXTURE_FIELDS, FixtureTable, Fixtures
from .contacts import CARRIED, CONTACT_FIELDS, MAX_POINTS, ContactBuffer, Contacts
from .joints import JOINT_FIELDS, JOINT_KINDS, JointTable, Joints
from .springs import SPRING_FIELDS, Springs
from .table import Table, allocate, f8, grown, i1, i4, i8
from .vertices import VERT_FIELDS, VertexPool, Verts

__all__ = ["BODY_FIELDS", "CIRCLE", "DYNAMIC", "KIND_NAMES", "KINDS", "KINEMATIC", "POLYGON", "STATIC", "Bodies",
           "CARRIED", "CONTACT_FIELDS", "MAX_POINTS", "ContactBuffer", "Contacts", "SPRING_FIELDS", "Springs",
           "JOINT_FIELDS", "JOINT_KINDS", "JointTable", "Joints", "FIXTURE_FIELDS", "FixtureTable", "Fixtures",
           "Table", "allocate", "f8", "grown", "i1", "i4", "i8", "VERT_FIELDS", "VertexPool", "Verts", "Store"]


class Store:
    """The tables of one world: ``bodies``, ``fixtures``, ``verts``, ``springs``, ``joints``, ``contacts``.

    ``joint_work`` is the solvers' scratch for the joint rows (built by physics/constraints/
    joints on first use and kept across mode switches; None while the world has no joints).
    """

    __slots__ = ("bodies", "fixtures", "verts", "springs", "joints", "contacts", "joint_work")

    def __init__(self):
        self.bodies = Table(BODY_FIELDS, Bodies, cap=64)
        self.fixtures = FixtureTable(cap=64)
        self.springs = Table(SPRING_FIELDS, Springs, cap=16)
        self.verts = VertexPool()
        self.joints = JointTable()
        self.contacts = ContactBuffer()
        self.joint_work = None
