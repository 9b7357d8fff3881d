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
    """``@row_inline``: a per-joint helper inlined into its caller by numba.  Without it every call
    passes the tables by value (B, J and the scratch: some 3 KB of array structs), which cost
    about 100 ns a call here; inlined, the pass over the joints is one flat loop."""
    return kernel(fn, inline="always")


def row_entry(fn):
    """``@row_entry``: ``@row_kernel`` that Python calls too (physics/_jit.py: ``entry``)."""
    return kernel(fn, entry=True)
