"""Make numba's IR inliner (``inline="always"``) cost linear time, not quadratic.

The core inlines its small geometric helpers at numba IR level (a call that passes the store's
namedtuples by value costs ~100 ns; inlined, a pair loop is one flat function).  numba 0.68's
``InlineWorker`` spends most of a cold compile on two things (cProfile of the sandbox's narrow
phase unit, 310 s profiled: 214 s in ``copy.deepcopy``, 91 s in the callee's frontend):

1. ``inline_ir`` deep-copies the callee one block at a time, each with a fresh memo, so every
   block drags a private copy of the function's whole ``Scope`` (every variable and location):
   O(blocks x variables) per call site, and the callee's scopes come out equal, not identical.
2. ``inline_function`` runs the callee's untyped pipeline again at every call site, and that
   pipeline inlines the callee's own callees again: nesting multiplies the work.

Here (1) one memo serves all the blocks of one copy (one copy of the scope, as in the source
IR) and (2) a callee's frontend IR is kept per (function, flags, locals, pipeline): the inliner
copies it before it mutates anything.  The IR that reaches type inference is the same (same
statements, same names), so the machine code is the same; tests/test_numba_inline.py checks
both that and that the patch is on.  Applied once, from physics/_jit.py; with another numba
version whose internals differ, nothing is patched (compiles are then just slower).
"""
from __future__ import annotations

import copy as _copy

_FRONTENDS: dict = {}
_ORIGINAL: list = []      # numba's own InlineWorker.inline_function, once patched (for unpatched())
APPLIED = False


class _BlockCopier:
    """Stands in for the ``copy`` module inside numba's inliner: consecutive ``deepcopy`` calls
    on the blocks of one IR share one memo (a new copy starts at a block already copied, or at
    a block of another scope)."""

    def __init__(self):
        from numba.core import ir
        self._block = ir.Block
        self._memo: dict = {}
        self._scope = None

    def deepcopy(self, x, memo=None):
        if memo is not None or not isinstance(x, self._block):
            return _copy.deepcopy(x, memo)
        if x.scope is not self._scope or id(x) in self._memo:
            self._memo, self._scope = {}, x.scope
        return _copy.deepcopy(x, self._memo)

    def __getattr__(self, name):
        return getattr(_copy, name)


def _inline_function(self, caller_ir, block, i, function, arg_typs=None):
    """numba's ``InlineWorker.inline_function`` with the callee's frontend IR kept (see (2))."""
    self.flags.enable_ssa = False          # what run_untyped_passes sets on the caller's flags
    key = (function, repr(self.flags), repr(sorted(self.locals.items())) if self.locals else "",
           type(self.pipeline))
    callee_ir = _FRONTENDS.get(key)
    if callee_ir is None:
        callee_ir = _FRONTENDS[key] = self.run_untyped_passes(function)
    return self.inline_ir(caller_ir, block, i, callee_ir, function.__code__.co_freevars, arg_typs=arg_typs)


class unpatched:
    """``with unpatched():`` numba's own inliner (tests compare the two)."""

    def __enter__(self):
        from numba.core import inline_closurecall as ic
        self._saved = ic.copy, ic.InlineWorker.inline_function
        if APPLIED:
            ic.copy, ic.InlineWorker.inline_function = _copy, _ORIGINAL[0]
        return self

    def __exit__(self, *exc):
        from numba.core import inline_closurecall as ic
        ic.copy, ic.InlineWorker.inline_function = self._saved



def apply() -> bool:
    """Patch numba's inliner once; False when this numba does not have the expected shape."""
    global APPLIED
    if APPLIED:
        return True
    try:
        from numba.core import inline_closurecall as ic
        worker = ic.InlineWorker
        ok = ic.copy is _copy and callable(worker.inline_ir) and callable(worker.run_untyped_passes)
    except (ImportError, AttributeError):
        return False
    if not ok:
        return False
    _ORIGINAL.append(worker.inline_function)
    ic.copy = _BlockCopier()
    worker.inline_function = _inline_function
    APPLIED = True
    return True
