"""A table that a world may not have (joints, springs), rebuilt from its flat arrays or left out.

``optional_joints(JF, JI)`` is None when ``JF`` is None, else the joint table's view
(store/flat.py); ``optional_springs(SF, SI)`` likewise for the springs.  It is resolved from the argument types while numba types the caller, so a
caller compiled for a world without joints contains no joint code and one with joints contains
no second, joint-free copy of the solver.  A plain ``if JF is None`` does not do this: numba
prunes that branch only when the argument's type is None itself, and otherwise compiles both
(the solver's joint-free variant then came along with every joint stage and its compile).
"""
from __future__ import annotations

from numba import types
from numba.extending import overload

from .table_type import make_table


def optional_joints(JF, JI):
    """The joints' view of ``(JF, JI)``, or None for a world without joints (``JF`` None)."""
    return None if JF is None else make_table("joints", (JF, JI))


def optional_springs(SF, SI):
    """The springs' view of ``(SF, SI)``, or None for a world without springs (``SF`` None): the
    spring solve (constraints/springs: the implicit system and its Newton refinement, some 30
    kernels and about 7 CPU s of a cold first step) is then not compiled."""
    return None if SF is None else make_table("springs", (SF, SI))


def _or_none(table):
    """The typing of an optional table: None for a None-typed first array, else ``table``."""
    def typing(F, I):
        if isinstance(F, types.NoneType):
            return lambda F, I: None
        return table
    return typing


# inline, and the table made in place (an intrinsic, not a kernel): it is built the caller's way,
# with or without numba's runtime, so a runtime-free caller counts no references
overload(optional_joints, inline="always")(_or_none(lambda F, I: make_table("joints", (F, I))))
overload(optional_springs, inline="always")(_or_none(lambda F, I: make_table("springs", (F, I))))
