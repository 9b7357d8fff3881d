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


def kernel(fn=None, **kw):
    """``@kernel``: numba ``njit(cache=True, fastmath=False)`` for the core's hot loops.

    fastmath stays off: determinism and IEEE NaN semantics matter more here
    (the finite check relies on NaN propagating).
    """
    opts = dict(cache=True, nogil=True)
    opts.update(kw)
    if fn is None:
        return lambda f: _njit(**opts)(f)
    return _njit(**opts)(fn)
