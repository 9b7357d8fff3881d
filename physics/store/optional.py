"""A table that a world may not have (joints), rebuilt from its flat arrays or left out.

``optional_joints(JF, JI)`` is None when ``JF`` is None, else the joint table's view
(store/flat.py).  It is resolved from the argument types while numba types the caller, so a
caller compiled for a world without joints contains no joint code and one with joints contains
no second, joint-free copy of the solver.  A plain ``if JF is None`` does not do this: numba
prunes that branch only when the argument's type is None itself, and otherwise compiles both
(the solver's joint-free variant then came along with every joint stage and its compile).
"""
from __future__ import annotations

from numba import types
from numba.extending import overload

from .flat import joints_view


def optional_joints(JF, JI):
    """The joints' view of ``(JF, JI)``, or None for a world without joints (``JF`` None)."""
    return None if JF is None else joints_view(JF, JI)


@overload(optional_joints, inline="always")  # returns arrays: built the caller's way
def _optional_joints(JF, JI):
    if isinstance(JF, types.NoneType):
        return lambda JF, JI: None
    return lambda JF, JI: joints_view(JF, JI)
