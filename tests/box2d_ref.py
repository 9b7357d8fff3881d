"""Where the tests find Box2D v3, the reference engine they run beside Stelkropp (not a test module).

The sources come from, in order: ``pytest --box2d-src DIR`` or ``$STELKROPP_BOX2D_SRC``, then the
workspace's ``../shared/reference/box2d-v3`` (bench/box2d/build.py: ``find_source``).  A clone with
neither (a user's own machine) skips the tests that need Box2D v3 and says where to point them; where
the sources exist (CI here) they always run, and a failed build is a failure, never a skip.  The
pyb2d3 wheel was evaluated as a fallback (docs/testing.md: it wraps Box2D 3.1, not the snapshot
the figures were measured on).
"""
from __future__ import annotations

import pytest

from bench.box2d import build as B


def sources_present() -> bool:
    """Is there a Box2D v3 source tree to build (whether or not it builds)?"""
    try:
        B.find_source()
    except B.BuildError:
        return False
    return True


def box2d_v3() -> B.Build:
    """The built shim and benchmark app; skips the calling test when no sources are known, fails
    when they are there but do not build."""
    try:
        B.find_source()
    except B.BuildError as exc:
        pytest.skip(f"Box2D v3 reference not available: {exc}; run with `pytest --box2d-src DIR` or set "
                    "STELKROPP_BOX2D_SRC to a Box2D v3 checkout (the workspace's ../shared/reference/box2d-v3 "
                    "is used when present)")
    assert B.available(), B.why_unavailable()
    return B.build()
