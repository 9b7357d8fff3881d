"""The sub-steps a scene calls for in ``soft_step``: more for thin or small dynamic bodies.

Four sub-steps hold a pyramid of 1 m boxes, but not Box2D v3's Card House (cards 2 mm x 0.4 m)
nor its Tiny Pyramid (5 cm boxes): their top card and top box move 1.9 m and 20 box sizes in
10 s, where Box2D v3 holds them to 0.035 m and 1.3 box sizes.  At eight sub-steps they hold
(0.026 m, 1.01 box sizes).  What they share is a body small against the contact model's own
lengths: the contacts' softness and push-out act within a few linear slops (5 mm), so a card
thinner than two slops or a box smaller than twenty rocks and slides where a large one rests.
Sub-steps scale the soft contacts' stiffness with the sub-step rate (Catto, "Solver2D", 2024), so
such scenes get eight; every other scene keeps four and pays nothing.  Measured side by side
in docs/reliability.md.

The rule reads only the dynamic bodies' shapes in their own frames, so it is deterministic and
changes only when the scene is edited; a user's ``substeps`` always wins.
"""
from __future__ import annotations

import numpy as np

from ...store.bodies import DYNAMIC
from ...store.fixtures import CAPSULE, CIRCLE, POLYGON

THIN = 2.0  # a dynamic shape thinner than this many linear slops (with a long side 10x that)
SMALL = 20.0  # a dynamic body whose largest shape is smaller than this many linear slops
SUBSTEPS = 8


def _extents(world):
    """(body slot, short side, long side) of each dynamic, non-sensor polygon, circle and capsule
    fixture, in the body's frame (a polygon's local bounding box, rounding included)."""
    st = world._store
    f = st.fixtures.arrays
    nf = st.fixtures.n
    kinds = st.bodies.arrays["kind"][f["body"][:nf]]
    keep = (kinds == DYNAMIC) & (f["sensor"][:nf] == 0) & np.isin(f["shape"][:nf], (POLYGON, CIRCLE, CAPSULE))
    idx = np.nonzero(keep)[0]
    local = st.verts.arrays["local"]
    out = []
    for i in idx:
        r = f["radius"][i]
        if f["shape"][i] == CIRCLE:
            out.append((f["body"][i], 2 * r, 2 * r))
            continue
        v = local[f["vstart"][i]: f["vstart"][i] + f["vcount"][i]]
        w, h = np.ptp(v[:, 0]) + 2 * r, np.ptp(v[:, 1]) + 2 * r
        out.append((f["body"][i], min(w, h), max(w, h)))
    return out


def fit(world) -> dict:
    """``{"substeps": (8, why)}`` when the scene has a thin or a small dynamic body (module doc)."""
    if world._store.bodies.n == 0:
        return {}
    slop = world.linear_slop
    ext = _extents(world)
    thin = [e for e in ext if e[1] < THIN * slop and e[2] >= 10 * THIN * slop]
    if thin:
        b, short, _ = min(thin, key=lambda e: e[1])
        return {"substeps": (SUBSTEPS, f"thin shapes: {_name(world, b)} is {_mm(short)} thick "
                                       f"(under {THIN:g} linear slops)")}
    size: dict = {}
    for b, _, long in ext:
        size[b] = max(size.get(b, 0.0), long)
    small = [(s, b) for b, s in size.items() if s < SMALL * slop]
    if small:
        s, b = min(small)
        return {"substeps": (SUBSTEPS, f"small bodies: {_name(world, b)} is {_mm(s)} across "
                                       f"(under {SMALL:g} linear slops)")}
    return {}


def _mm(x: float) -> str:
    return f"{x * 1000:.3g} mm" if x < 0.1 else f"{x:.3g} m"


def _name(world, slot) -> str:
    body = world._handles.get(int(world._store.bodies.arrays["id"][slot]))
    return f"body '{body.name}'" if body is not None and body.name else f"body {int(slot)}"
