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


def row_part(fn):
    """``@row_part``: a joint-level step of a verb (one kind's row builder or preparation, the
    free rows' or the equality block's solve), compiled once as a function of its own and called
    once per joint.  Inlining these into every verb typed and optimised each kind's code once per
    verb; over the compact tables (store/table_type.py) a call passes a few array structs, so
    compiling each once costs the step little.  The small helpers inside stay ``row_inline``."""
    return kernel(fn)


def row_entry(fn):
    """``@row_entry``: ``@row_kernel`` that Python calls too (physics/_jit.py: ``entry``)."""
    return kernel(fn, entry=True)
