"""Whether the kinds of the bodies the joints join changed since the last look (one compiled
call over the flat tables, cheap enough to ask every step)."""
from __future__ import annotations

from ..._jit import kernel
from ...store.flat import bodies_view, joints_view


@kernel(entry=True, runtime=True)
def kinds_changed(JF, JI, BF, BI, nj, seen):
    """``kinds_changed_in`` over the joint and body tables' flat arrays."""
    return kinds_changed_in(joints_view(JF, JI), bodies_view(BF, BI), nj, seen)


@kernel
def kinds_changed_in(J, B, nj, seen):
    """Compare the kind of each joint's two bodies (-1 for the world) with ``seen`` (2 per joint,
    at least ``2 * nj`` long), write the current ones into it, and say whether any differed."""
    changed = False
    for j in range(nj):
        ka = B.kind[J.a[j]]
        kb = B.kind[J.b[j]] if J.b[j] >= 0 else -1
        if seen[2 * j] != ka or seen[2 * j + 1] != kb:
            changed = True
            seen[2 * j] = ka
            seen[2 * j + 1] = kb
    return changed
