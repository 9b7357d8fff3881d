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

from .flat import joints_view, springs_view


def optional_joints(JF, JI):
    """The joints' view of ``(JF, JI)``, or None for a world without joints (``JF`` None)."""
    return None if JF is None else joints_view(JF, JI)


@overload(optional_joints, inline="always")  # returns arrays: built the caller's way
def _optional_joints(JF, JI):
    if isinstance(JF, types.NoneType):
        return lambda JF, JI: None
    return lambda JF, JI: joints_view(JF, JI)


def optional_springs(SF, SI):
    """The springs' view of ``(SF, SI)``, or None for a world without springs (``SF`` None): the
    spring solve (constraints/springs: the implicit system and its Newton refinement, about a fifth
    of soft_step's cold compile) is then not compiled."""
    return None if SF is None else springs_view(SF, SI)


@overload(optional_springs, inline="always")  # returns arrays: built the caller's way
def _optional_springs(SF, SI):
    if isinstance(SF, types.NoneType):
        return lambda SF, SI: None
    return lambda SF, SI: springs_view(SF, SI)
