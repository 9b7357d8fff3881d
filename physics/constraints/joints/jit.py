"""The decorators of the joint kernels.

Every per-joint helper takes the joint table and scratch as namedtuples of
arrays; like every kernel that allocates nothing they are compiled without
numba's runtime, so passing them costs no reference counting (physics/_jit.py).
"""
from __future__ import annotations

from ..._jit import kernel


def row_kernel(fn):
    """``@row_kernel``: ``physics._jit.kernel`` (see the module doc)."""
    return kernel(fn)


def row_inline(fn):
    """``@row_inline``: a per-joint helper LLVM inlines into its caller.  Without it every call
    passes the tables by value (J and the scratch JW, each array's struct copied), which costs
    more than a pass's own arithmetic on a joint: the velocity passes' joint-level work (the free
    rows, the equality block, the lone block, the motor and mouse joints, the warm start) is
    inlined into the verb's loop over the joints, its one caller, so each is still typed once
    (docs/benchmarks.md has what it saved)."""
    return kernel(fn, forceinline=True)


def row_part(fn):
    """``@row_part``: a joint-level step compiled once as a function of its own and called once per
    joint: a kind's row builder or preparation, which run once per move or step and are reached
    from more than one verb (inlined, each kind's code would be typed and optimised once per
    verb).  The small helpers inside stay ``row_inline``."""
    return kernel(fn)


def row_entry(fn):
    """``@row_entry``: ``@row_kernel`` that Python calls too (physics/_jit.py: ``entry``)."""
    return kernel(fn, entry=True)
