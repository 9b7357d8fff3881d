"""physics/_numba_inline.py: numba's IR inliner made linear.  The patch must be on (a numba
upgrade that changes the inliner's shape turns it off silently: this says so), must give the
compiler the same code (the machine code's instruction mix and the results are the same as with
numba's own inliner), and must do the work it claims to save (each inlined callee's frontend
runs once, not once per call site and nesting level)."""
from __future__ import annotations

import collections
import contextlib
import re

import numpy as np
from numba import njit
from numba.core import inline_closurecall as ic

import physics  # noqa: F401  (applies the patch)
from physics import _numba_inline


def _leaf(a, i):
    s = 0.0
    for k in range(a.shape[1]):
        s += a[i, k] * (k + 1)
    return s if s > 0.0 else -s


def _mid(a, i, j):
    return _leaf(a, i) - 2.0 * _leaf(a, j)


def _top(a):
    out = 0.0
    for i in range(a.shape[0] - 1):
        out += _mid(a, i, i + 1) + _mid(a, i + 1, i)
    return out


def _build():
    """Fresh dispatchers of the three functions (each compile starts from nothing)."""
    leaf = njit(inline="always")(_leaf)
    g = {**_mid.__globals__, "_leaf": leaf}
    mid = njit(inline="always")(type(_mid)(_mid.__code__, g, "_mid"))
    g2 = {**_top.__globals__, "_mid": mid}
    return njit(type(_top)(_top.__code__, g2, "_top"))


def _opcodes(llvm: str) -> collections.Counter:
    """The LLVM instruction mix of a module (names differ between two compiles, opcodes do not)."""
    ops = re.findall(r"^\s+(?:%\S+ = )?([a-z]+)\b", llvm, re.M)
    return collections.Counter(ops)


def _compile_counting(unpatched: bool):
    calls = []
    real = ic.InlineWorker.run_untyped_passes

    def counting(self, func, enable_ssa=False):
        calls.append(func.__name__)
        return real(self, func, enable_ssa)
    ic.InlineWorker.run_untyped_passes = counting
    _numba_inline._FRONTENDS.clear()
    try:
        with _numba_inline.unpatched() if unpatched else contextlib.nullcontext():
            top = _build()
            top.compile("f8(f8[:, :])")
    finally:
        ic.InlineWorker.run_untyped_passes = real
    return top, calls


def test_the_patch_is_on():
    assert _numba_inline.APPLIED, "physics/_numba_inline.py did not patch this numba's inliner"
    assert isinstance(ic.copy, _numba_inline._BlockCopier)


def test_same_code_less_work():
    fast, fast_calls = _compile_counting(unpatched=False)
    slow, slow_calls = _compile_counting(unpatched=True)
    # numba's own: _mid's frontend at each of its 2 call sites, and each of those runs _leaf's at
    # its 2 call sites: 2 + 4; patched: each callee once
    assert sorted(slow_calls) == ["_leaf"] * 4 + ["_mid"] * 2
    assert sorted(fast_calls) == ["_leaf", "_mid"]
    sig = fast.signatures[0]
    assert _opcodes(fast.inspect_llvm(sig)) == _opcodes(slow.inspect_llvm(sig))
    a = np.random.default_rng(1).normal(size=(7, 5))
    assert fast(a) == slow(a) == _top(a)        # the same arithmetic as Python's, in order
