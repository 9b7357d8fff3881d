"""A cycle counter readable inside compiled code, for the step driver's profile.

numba has no clock of its own in nopython mode; LLVM's ``readcyclecounter`` (the time-stamp
counter on x86) costs a few nanoseconds and caches with the kernel that uses it.  The driver
stamps it at each stage boundary and Python scales the stamps by the step's wall time
(perf_counter around the call), so no cycles-per-second calibration is needed.
"""
from __future__ import annotations

from llvmlite import ir
from numba import types
from numba.core import cgutils
from numba.extending import intrinsic


@intrinsic
def cycles(typingctx):
    """The processor's cycle counter (an int64 that only grows within a process)."""
    def codegen(context, builder, signature, args):
        fnty = ir.FunctionType(ir.IntType(64), [])
        fn = cgutils.get_or_insert_function(builder.module, fnty, "llvm.readcyclecounter")
        return builder.call(fn, [])
    return types.int64(), codegen
