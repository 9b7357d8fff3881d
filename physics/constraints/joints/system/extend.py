"""The global system grown by joints added after it was built, without building it again.

The system is block diagonal by component (joints that share a moving body, topology.py), and
a build lists the components by their lowest joint.  Joints added since the last build have the
highest numbers; when none of them shares a moving body with an earlier joint, their components
are new and come last in a full build too.  The full build is then the old system followed by
the new joints' own system, its rows, entries and contributions numbered on from the old ones'
counts: the same arrays (tests/test_joint_system_extend.py), for the cost of the new joints
alone (a world that gains ragdolls while it runs: Box2D v3's rain benchmark).
"""
from __future__ import annotations

import numpy as np

from ....store import DYNAMIC
from . import ldl
from .topology import STRUCTURE, _system, build


def new_structures_only(J, nj0: int, nj: int, kinds: np.ndarray) -> bool:
    """Whether no joint of nj0..nj-1 touches a dynamic body an earlier joint touches."""
    dyn = np.asarray(kinds) == DYNAMIC
    seen = np.zeros(len(dyn), bool)
    a, b = J.a[:nj0], J.b[:nj0]
    seen[a] = True
    seen[b[b >= 0]] = True
    seen &= dyn
    a, b = J.a[nj0:nj], J.b[nj0:nj]
    return not (seen[a].any() or seen[b[b >= 0]].any())


def extend(S, J, nj0: int, nj: int, kinds: np.ndarray, jcap: int):
    """(system, seq) for joints 0..nj-1, with room for ``jcap`` joints, from ``S``, the system
    of joints 0..nj0-1, when ``new_structures_only`` holds; ``seq`` as topology.build's, for the
    new joints (those before nj0 keep theirs)."""
    N, seq = build(J, nj, kinds, jcap, lo=nj0)
    r0, c0, e0 = (int(v) for v in S.dims[:3])
    r1, c1, e1 = (int(v) for v in N.dims[:3])
    nr, nc, ne = r0 + r1, c0 + c1, e0 + e1
    out = _system(nr, ne, nc, 0, jcap)
    out.jrow[: len(S.jrow)] = S.jrow
    new = N.jrow >= 0
    out.jrow[new] = N.jrow[new] + r0
    for name, old, add, shift in (("row_j", r0, r1, 0), ("row_r", r0, r1, 0), ("Ai", e0, e1, r0)):
        dst = getattr(out, name)
        dst[:old] = getattr(S, name)[:old]
        dst[old:old + add] = getattr(N, name)[:add] + shift
    out.Ap[: r0 + 1] = S.Ap[: r0 + 1]
    out.Ap[r0:] = N.Ap[: r1 + 1] + e0
    out.contrib[:c0] = S.contrib[:c0]
    out.contrib[c0:] = N.contrib[:c1]
    out.contrib[c0:, 0] += e0  # the entry each contribution adds to
    ldl.symbolic(nr, out.Ap, out.Ai, out.Parent, out.Lnz, out.Flag, out.Lp)
    full = _system(nr, ne, nc, int(out.Lp[nr]), jcap)  # with room for L's entries
    for name in STRUCTURE:
        getattr(full, name)[...] = getattr(out, name)
    return full, seq
