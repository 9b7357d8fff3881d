"""The spring table: damped springs between two bodies or a body and a world point."""
from __future__ import annotations

from .table import f8, i4, i8
from .table_view import view_class

SPRING_FIELDS = {
    "a": ((), i4),          # body slot
    "b": ((), i4),          # body slot, or -1 for a world anchor
    "la": ((2,), f8),       # anchor on a, relative to a's centre of mass (body frame)
    "lb": ((2,), f8),       # anchor on b likewise, or the world point when b == -1
    "k": ((), f8),          # stiffness N/m
    "c": ((), f8),          # damping N s/m along the spring axis
    "rest": ((), f8),       # rest length m
    "id": ((), i8),
}
Springs = view_class("Springs", SPRING_FIELDS, "springs")
