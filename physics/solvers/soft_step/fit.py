"""The sub-steps and contact stiffness a scene calls for in ``soft_step``: more sub-steps for thin
or small dynamic bodies and for a heavy body resting on a much lighter one, stiffer contacts for
a very heavy one.

Four sub-steps hold a pyramid of 1 m boxes, but not Box2D v3's Card House (cards 2 mm x 0.4 m)
nor its Tiny Pyramid (5 cm boxes): their top card and top box move 1.9 m and 20 box sizes in
10 s, where Box2D v3 holds them to 0.035 m and 1.3 box sizes.  At eight sub-steps they hold
(0.026 m, 1.01 box sizes).  What they share is a body small against the contact model's own
lengths: the contacts' softness and push-out act within a few linear slops (5 mm), so a card
thinner than two slops or a box smaller than twenty rocks and slides where a large one rests.
Sub-steps scale the soft contacts' stiffness with the sub-step rate (Catto, "Solver2D", 2024), so
such scenes get eight; so does a body above one a hundred times lighter, which the soft contact
between them lets sink into it (``_heavy_on_light``).  Every other scene keeps four
and pays nothing.  A soft contact's spring is mass-weighted (its stiffness is the rows' effective
mass times omega^2), so what a light body under a heavy one sinks grows with the mass ratio, not
with the sub-steps: a 1000 kg box on a 1 kg box sinks 8.6 cm at 8, 12, 16 or 24 sub-steps at the
default 60 Hz, 3.5 cm at 120 Hz.  Above STIFF:1 the contacts take a quarter of the sub-step rate,
the stiffest Box2D v3's soft step allows (its contact hertz cap); 400:1 (HighMassRatio2) keeps the
default, where stiffer contacts knock the small boxes from under the falling one.  Measured side
by side in docs/reliability.md.

The rule reads the dynamic bodies' shapes, masses and where they stand, so it is deterministic and
changes only when the scene is edited; a user's ``substeps`` or ``contact_hertz`` always wins.
"""
from __future__ import annotations

import numpy as np

from ...store.bodies import DYNAMIC
from ...store.fixtures import CAPSULE, CIRCLE, POLYGON

THIN = 2.0  # a dynamic shape thinner than this many linear slops (with a long side 10x that)
SMALL = 20.0  # a dynamic body whose largest shape is smaller than this many linear slops
HEAVY = 100.0  # a dynamic body above one this many times lighter (resting or falling on it)
PAIRS = 1_000_000  # heavy x light candidate pairs looked at, at most (a larger scene is not judged)
SUBSTEPS = 8
STIFF = 1000.0  # above one this many times lighter, the contacts are also made as stiff as allowed


def _extents(world):
    """(body slot, short side, long side) arrays, one entry per dynamic, non-sensor polygon,
    circle and capsule fixture in fixture order, in the body's frame (a polygon's local bounding
    box, rounding included).  numpy over the tables: it runs again after every edit."""
    st = world._store
    f = st.fixtures.arrays
    nf = st.fixtures.n
    body, shape = f["body"][:nf], f["shape"][:nf]
    keep = (st.bodies.arrays["kind"][body] == DYNAMIC) & (f["sensor"][:nf] == 0) & \
        np.isin(shape, (POLYGON, CIRCLE, CAPSULE))
    idx = np.nonzero(keep)[0]
    r2 = 2 * f["radius"][idx]
    w, h = r2.copy(), r2.copy()  # a circle: its diameter both ways
    cored = shape[idx] != CIRCLE
    if cored.any():
        pi = idx[cored]
        count = f["vcount"][pi]
        first = np.cumsum(count) - count
        k = np.arange(count.sum()) - np.repeat(first, count)
        v = st.verts.arrays["local"][np.repeat(f["vstart"][pi], count) + k]
        ptp = np.maximum.reduceat(v, first) - np.minimum.reduceat(v, first)
        w[cored] = ptp[:, 0] + r2[cored]
        h[cored] = ptp[:, 1] + r2[cored]
    return body[idx], np.minimum(w, h), np.maximum(w, h)


def fit(world) -> dict:
    """``{"substeps": (8, why)}`` when the scene has a thin, a small or a heavy-on-light dynamic
    body, and ``"contact_hertz"`` as well above STIFF:1 (module doc)."""
    n = world._store.bodies.n
    if n == 0:
        return {}
    out = {}
    why = _small_or_thin(world, n)
    if why:
        out["substeps"] = (SUBSTEPS, why)
    pair = _heavy_on_light(world)
    if pair is not None:
        h, l, mh, ml = pair
        ratio = f"{_name(world, h)} ({mh:.3g} kg) is above {_name(world, l)} ({ml:.3g} kg), {mh / ml:.0f}:1"
        out.setdefault("substeps", (SUBSTEPS, f"mass ratio: {ratio} (at least {HEAVY:g}:1)"))
        if mh >= STIFF * ml:
            hertz = 0.25 * SUBSTEPS / world.dt
            out["contact_hertz"] = (hertz, f"mass ratio: {ratio} (at least {STIFF:g}:1): contacts at a quarter "
                                           f"of the rate of {SUBSTEPS} sub-steps, the stiffest soft contacts")
    return out


def _small_or_thin(world, n):
    """Why the scene needs more sub-steps for its shapes ('' if it does not): its thinnest shape
    under THIN linear slops, else its smallest body under SMALL."""
    slop = world.linear_slop
    body, short, long = _extents(world)
    thin = np.nonzero((short < THIN * slop) & (long >= 10 * THIN * slop))[0]
    if len(thin):
        t = thin[np.argmin(short[thin])]  # the thinnest, the first of equals
        return f"thin shapes: {_name(world, body[t])} is {_mm(short[t])} thick (under {THIN:g} linear slops)"
    size = np.zeros(n)  # each body's largest shape
    np.maximum.at(size, body, long)
    small = np.nonzero((size > 0.0) & (size < SMALL * slop))[0]
    if len(small):
        b = small[np.argmin(size[small])]  # the smallest, the lowest slot of equals
        return f"small bodies: {_name(world, b)} is {_mm(size[b])} across (under {SMALL:g} linear slops)"
    return ""


def _heavy_on_light(world):
    """(heavy slot, light slot, masses) of a dynamic body above one HEAVY times lighter, as the
    scene stands: its bounding box bottom above the light one's top along gravity (or below it
    by at most two speculative distances: resting on it) and overlapping it across, so that it
    rests or will land on it.  Box2D v3's HighMassRatio2 (a 400 kg box dropped onto two 1 kg boxes)
    sinks 0.49 m at four sub-steps, 0.018 m at eight (Box2D v3: 0.086 m).  None if there is
    none, or more than PAIRS candidate pairs."""
    st = world._store
    n = st.bodies.n
    kind, m = st.bodies.arrays["kind"][:n], st.bodies.arrays["m"][:n]
    dyn = np.nonzero(kind == DYNAMIC)[0]
    gx, gy = world.gravity
    if len(dyn) < 2 or (gx == 0.0 and gy == 0.0) or m[dyn].max() < HEAVY * m[dyn].min():
        return None
    heavy = dyn[m[dyn] >= HEAVY * m[dyn].min()]
    light = dyn[m[dyn] * HEAVY <= m[dyn].max()]
    if len(heavy) * len(light) > PAIRS:
        return None
    box = _body_boxes(st, n)
    up = 1 if abs(gy) >= abs(gx) else 0  # the axis gravity runs along, and which way is up
    sign = -1.0 if (gy if up else gx) < 0.0 else 1.0
    lo, hi = (box[:, up], box[:, up + 2]) if sign < 0 else (-box[:, up + 2], -box[:, up])
    across = 1 - up
    H, L = heavy[:, None], light[None, :]
    d = world.speculative_distance
    gap = hi[L] - lo[H]  # the light one's top less the heavy one's bottom
    ok = ((m[H] >= HEAVY * m[L]) & (gap <= 2.0 * d)
          & (box[H, across] < box[L, across + 2]) & (box[L, across] < box[H, across + 2]))
    if not ok.any():
        return None
    i, j = np.unravel_index(np.argmax(np.where(ok, m[H] / m[L], 0.0)), ok.shape)
    return int(heavy[i]), int(light[j]), float(m[heavy[i]]), float(m[light[j]])


def _body_boxes(st, n):
    """Each body's bounding box (min x, min y, max x, max y) over its fixtures where the bodies
    stand now, from their core vertices (rounded by their radius) and circles' centres: numpy
    here, so that asking what a scene calls for compiles nothing."""
    f = st.fixtures.arrays
    nf = st.fixtures.n
    B = st.bodies.arrays
    body = f["body"][:nf]
    q, x = B["q"][body], B["x"][body]
    c, s = np.cos(q), np.sin(q)
    count = np.where(f["vcount"][:nf] > 0, f["vcount"][:nf], 1)  # a circle: its centre
    owner = np.repeat(np.arange(nf), count)
    k = np.arange(len(owner)) - np.repeat(np.cumsum(count) - count, count)
    local = np.where((f["vcount"][:nf] > 0)[owner, None],
                     st.verts.arrays["local"][np.minimum(f["vstart"][:nf][owner] + k, len(st.verts.arrays["local"]) - 1)],
                     f["center"][:nf][owner])
    px = x[owner, 0] + c[owner] * local[:, 0] - s[owner] * local[:, 1]
    py = x[owner, 1] + s[owner] * local[:, 0] + c[owner] * local[:, 1]
    r = f["radius"][:nf][owner]
    box = np.empty((n, 4))
    box[:, :2], box[:, 2:] = np.inf, -np.inf
    b = body[owner]
    np.minimum.at(box[:, 0], b, px - r)
    np.minimum.at(box[:, 1], b, py - r)
    np.maximum.at(box[:, 2], b, px + r)
    np.maximum.at(box[:, 3], b, py + r)
    return box


def _mm(x: float) -> str:
    return f"{x * 1000:.3g} mm" if x < 0.1 else f"{x:.3g} m"


def _name(world, slot) -> str:
    body = world._handles.get(int(world._store.bodies.arrays["id"][slot]))
    return f"body '{body.name}'" if body is not None and body.name else f"body {int(slot)}"
