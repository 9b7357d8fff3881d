"""The one place that configures numba for the whole core.

Numba's on-disk cache is invalidated only when the file holding a function
changes, not when a kernel it calls (in another module) changes.  Keying the
cache directory on a hash of every source file in ``physics/`` makes a stale
cache impossible: any edit anywhere selects a fresh directory.
"""
from __future__ import annotations

import hashlib
import os
import shutil
from pathlib import Path

_PKG = Path(__file__).resolve().parent


def _source_hash() -> str:
    h = hashlib.sha1()
    for p in sorted(_PKG.rglob("*.py")):
        h.update(str(p.relative_to(_PKG)).encode())
        h.update(p.read_bytes())
    return h.hexdigest()[:16]


def _cache_root() -> Path:
    base = os.environ.get("STELKROPP_CACHE_DIR")
    if base:
        return Path(base)
    xdg = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(xdg) / "stelkropp"


def _configure_cache() -> Path | None:
    if "NUMBA_CACHE_DIR" in os.environ:  # the user chose; respect it
        return None
    root = _cache_root() / "numba"
    target = root / _source_hash()
    try:
        target.mkdir(parents=True, exist_ok=True)
        # keep the three newest caches, drop older ones (each is a few MB)
        olds = sorted((d for d in root.iterdir() if d.is_dir() and d != target),
                      key=lambda d: d.stat().st_mtime, reverse=True)
        for d in olds[2:]:
            shutil.rmtree(d, ignore_errors=True)
    except OSError:
        return None
    os.environ["NUMBA_CACHE_DIR"] = str(target)
    import numba.core.config as cfg
    cfg.CACHE_DIR = str(target)
    return target


CACHE_DIR = _configure_cache()

from numba import njit as _njit  # noqa: E402  (after the cache dir is set)


def kernel(fn=None, *, runtime: bool = False, entry: bool = False, **kw):
    """``@kernel``: numba ``njit(cache=True, fastmath=False)`` for the core's hot loops.

    fastmath stays off: determinism and IEEE NaN semantics matter more here
    (the finite check relies on NaN propagating).

    ``runtime``: compile with numba's runtime (NRT).  Only a kernel that allocates an array, or
    returns one, needs it; without it no array a kernel binds or passes on is reference-counted
    (with it, each of a table's 20-26 column arrays costs two atomic updates per call) and the
    kernel compiles to less code.  It is set on every kernel, never inherited: numba otherwise
    compiles a callee with its first caller's setting, so the code would depend on which caller
    compiled first.  ``python -m physics precompile`` refuses a runtime-free kernel that returns an
    array (compile_checks.py): its caller would release a reference it was never given.

    ``forceinline=True``: LLVM inlines it wherever a caller links it (numba's option: the function
    is marked ``alwaysinline``).  It is still typed once per signature, as numba's IR-level
    ``inline="always"`` is not (that one types the body again at every call site).

    ``entry``: Python calls it.  Only entries get numba's Python wrapper (the code that unboxes
    every argument, for a table namedtuple some 26 arrays); every other kernel is compiled
    without it and without the C-callable wrapper, which took about a third of a cold compile
    (the default scene's first step 57 -> 40 CPU s).  Calling a kernel that is not an entry from
    Python raises RuntimeError naming it (numba would jump to a wrapper that is not there).
    """
    opts = dict(cache=True, nogil=True, _nrt=runtime)
    opts.update(kw)
    wrap = (lambda f: _njit(**opts)(f)) if entry else (lambda f: _internal(f, opts))
    return wrap if fn is None else wrap(fn)


def direct(dispatcher, *args):
    """``dispatcher``'s compiled function for the numba types of ``args``, to call with arguments of
    exactly those types.  A call through the dispatcher types every argument first; for a numba
    StructRef (the step's pack) that typing is most of a small world's step (about 0.9 of 1.1 us
    here).  Compiles (or loads from the cache) what is missing; falls back to the dispatcher where
    numba keeps no Python entry for the overload (NUMBA_DISABLE_JIT)."""
    if _config.DISABLE_JIT:
        return dispatcher
    from numba import typeof
    sig = tuple(typeof(a) for a in args)
    cres = dispatcher.overloads.get(sig)
    if cres is None:
        dispatcher.compile(sig)
        cres = dispatcher.overloads.get(sig)
    entry = getattr(cres, "entry_point", None)
    return dispatcher if entry is None else entry


from numba.core import config as _config, cpu as _cpu  # noqa: E402
from numba.core.types import unliteral as _unliteral  # noqa: E402
from numba.core.registry import CPUDispatcher as _CPUDispatcher, CPUTarget as _CPUTarget  # noqa: E402
from numba.core.registry import cpu_target as _cpu_target  # noqa: E402


class _PlainArguments:
    """Compiled callers' constant arguments typed as plain values: numba would compile a kernel
    once per constant (``Literal[int](3)``), where one overload serves them all, and LLVM folds
    the constant anyway once it inlines the callee (``forceinline``)."""

    def get_call_template(self, args, kws):
        return super().get_call_template(tuple(_unliteral(a) for a in args),
                                         {k: _unliteral(v) for k, v in kws.items()})


class _InternalDispatcher(_PlainArguments, _CPUDispatcher):
    """A kernel that only compiled code calls (see ``kernel``'s ``entry``)."""

    def __call__(self, *args, **kws):
        f = self.py_func
        raise RuntimeError(f"{f.__module__}.{f.__qualname__} is a kernel only compiled code calls: it has no "
                           "Python entry (physics/_jit.py: kernel(entry=True))")


def _internal(f, opts: dict):
    """``f`` as an internal kernel: numba's njit options without the Python and C wrappers (the
    plain function under NUMBA_DISABLE_JIT, as njit gives)."""
    if _config.DISABLE_JIT:
        return f
    o = dict(opts, nopython=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
    cache = o.pop("cache")
    disp = _InternalDispatcher(f, targetoptions=o)
    if cache:
        disp.enable_caching()
    return disp


# -- noalias kernels ----------------------------------------------------------------------------
# LLVM vectorises a loop over several arrays only when it may assume they do not overlap; numba
# has no public switch for that, so a dispatcher whose target options set ``flags.noalias``
# (numba internals, checked against numba 0.68: tests/test_coloured_solve.py greps the machine
# code for vector instructions, so a numba that drops the flag fails there, not silently).
# Measured on the coloured contact solve: ~2x per manifold (../shared/notes/solver-speed.md).
class _NoAliasOptions(_cpu.CPUTargetOptions):
    def finalize(self, flags, options):
        super().finalize(flags, options)
        flags.noalias = True


class _NoAliasTarget(_CPUTarget):
    options = _NoAliasOptions

    @property
    def target_context(self):  # numba's own CPU contexts: the kernels mix with every other
        return _cpu_target.target_context

    @property
    def typing_context(self):
        return _cpu_target.typing_context


class _NoAliasDispatcher(_PlainArguments, _CPUDispatcher):
    targetdescr = _NoAliasTarget("cpu")


def kernel_noalias(fn=None, *, runtime: bool = False, **kw):
    """``@kernel_noalias``: as ``@kernel``, and every array argument is promised to share no
    memory with any other (the caller's duty: pass distinct arrays only)."""
    opts = dict(nogil=True, nopython=True, _nrt=runtime)
    opts.update(kw)
    cache = opts.pop("cache", True)  # a decorator option (njit's), not a target option

    def wrap(f):
        if _config.DISABLE_JIT:
            return f
        disp = _NoAliasDispatcher(f, targetoptions=opts)
        if cache:
            disp.enable_caching()
        return disp
    return wrap if fn is None else wrap(fn)
