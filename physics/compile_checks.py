"""What the core's kernels must hold where numba's runtime stops: arrays cross it in neither direction.

A kernel compiled without numba's runtime (the default of physics/_jit.py) keeps no reference
counts.  Two ways to get that wrong, both silent until much later:

- it returns an array it was given: a caller with the runtime then releases a reference it was
  never handed, and the array is freed while still in use (heap corruption, a crash far away);
- it receives an array from a kernel with the runtime (a fresh one, or a view): it never releases
  that reference, so the memory is never freed, or it passes the array on to a caller that does.

A kernel that returns arrays is compiled with ``runtime=True`` and so are its callers, or it is
inlined so that it takes its caller's setting (store/flat.py's views).  This listens to numba's
compile events (its public event API) and names every compiled kernel that breaks either rule.
"""
from __future__ import annotations

from contextlib import contextmanager

from numba.core import event, types

from .store.table_type import SourcesType


def holds_array(t) -> bool:
    """Whether a numba type is an array, a store table (store/table_type.py), a record of arrays
    (store/segments.py) or a tuple (named or not) holding one."""
    if isinstance(t, (types.Array, SourcesType)):
        return True
    if isinstance(t, types.BaseTuple):
        return any(holds_array(x) for x in t.types)
    return False


def _name(disp) -> str:
    f = disp.py_func
    return f"{f.__module__}.{f.__qualname__}"


def _runtime(disp) -> bool:
    return disp.targetoptions.get("_nrt", True)


def _array_sources(cres):
    """Names of the kernels with the runtime that hand arrays to the compiled function ``cres``."""
    fd = cres.fndesc
    for expr, sig in (fd.calltypes or {}).items():
        if getattr(expr, "op", None) != "call" or sig is None:
            continue
        callee = fd.typemap.get(expr.func.name)
        if isinstance(callee, types.Dispatcher) and _runtime(callee.dispatcher) and holds_array(sig.return_type):
            yield _name(callee.dispatcher)


class _Check(event.Listener):
    """A listener that looks at each compile when it ends; ``bad`` keeps what it named."""

    def __init__(self):
        self.bad: list[str] = []

    def on_start(self, ev):
        pass


class ReturnCheck(_Check):
    """Raises RuntimeError at the compile of a runtime-free kernel that returns an array or takes
    one from a kernel with the runtime."""

    def on_end(self, ev):
        disp = ev.data["dispatcher"]
        if _runtime(disp):
            return
        cres = disp.overloads.get(tuple(ev.data["args"]))
        if cres is None:  # the compile failed: numba raises that itself
            return
        found = []
        if holds_array(cres.signature.return_type):
            found.append(f"{_name(disp)} returns {cres.signature.return_type}")
        found += [f"{_name(disp)} takes arrays from {src}" for src in sorted(set(_array_sources(cres)))]
        if found:
            self.bad += found
            # raised here, before the caller runs the kernel: a wrong count may crash the process
            raise RuntimeError("arrays cross numba's runtime boundary (give these kernels runtime=True, "
                               "physics/_jit.py):\n  " + "\n  ".join(found))


@contextmanager
def returns_checked():
    """Within the block, each compile of a runtime-free kernel is checked (RuntimeError naming
    the kernel at its compile)."""
    check = ReturnCheck()
    with event.install_listener("numba:compile", check):
        yield check


class LiteralCheck(_Check):
    """Names the core's kernels compiled for a literal argument: numba compiles a kernel once per
    literal constant it is called with (``f(x, True)`` and ``f(x, False)`` are two kernels, and a
    counter that starts at a literal 0 and is passed on costs one more), so a call passes plain
    values instead (``np.bool_(True)``, ``np.int64(0)``).  numba's own library is not checked."""

    def on_end(self, ev):
        disp = ev.data["dispatcher"]
        module = disp.py_func.__module__ or "numba"  # numba's generated overloads have none
        if module.startswith("numba"):
            return
        lit = [f"argument {i}: {t}" for i, t in enumerate(ev.data["args"]) if isinstance(t, types.Literal)]
        if lit:
            self.bad.append(f"{_name(disp)} ({', '.join(lit)})")


@contextmanager
def literals_checked():
    """Within the block, every kernel compiled for a literal argument is noted; RuntimeError
    naming them all when the block ends."""
    check = LiteralCheck()
    with event.install_listener("numba:compile", check):
        yield check
    if check.bad:
        raise RuntimeError("kernels compiled for literal arguments (pass np.int64(...) or np.bool_(...) "
                           "instead of a constant):\n  " + "\n  ".join(sorted(set(check.bad))))
