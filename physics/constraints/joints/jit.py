"""The decorator of the joint kernels: numba without reference counting.

Every per-joint helper takes the joint table and scratch as namedtuples of
arrays.  Numba increfs and decrefs every array of every such argument on entry
to and exit from a compiled function (33 atomic operations for the table and
the scratch), which cost about 0.6 us per call here, far more than the row
arithmetic.  These kernels allocate nothing, so they are compiled without the
runtime's reference counting (``_nrt=False``): a call then costs what a call
costs (1.5 ns measured).  Cached like every other kernel (physics/_jit.py).
"""
from __future__ import annotations

from ..._jit import kernel


def row_kernel(fn):
    """``@row_kernel``: ``physics._jit.kernel`` without reference counting (see the module doc)."""
    return kernel(fn, _nrt=False)


def row_inline(fn):
    """``@row_inline``: a per-joint helper inlined into its caller by numba.  Without it every call
    passes the tables by value (B, J and the scratch: some 3 KB of array structs), which cost
    about 100 ns a call here; inlined, the pass over the joints is one flat loop."""
    return kernel(fn, _nrt=False, inline="always")
