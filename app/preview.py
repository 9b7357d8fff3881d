"""The scene drawn before any kernel is compiled: render data in plain numpy.

``world.render_data()`` refreshes world-space vertices with a numba kernel, which a cold first
launch has not compiled yet.  ``render_data(world)`` computes the same arrays with numpy from the
world's store (vertex i of a polygon: x + R(q) local_i; the AABBs unfattened, as the world's own
refresh gives them with dt = 0 plus half the speculative margin) and writes nothing into the
world.  ``hold(world)`` hands these to all code that asks the world for its render data (the
camera framing, picking, hover, the selection's handles), so the first frame shows the scene,
framed, and the user can select, inspect, pan and zoom while the kernels compile.
"""
from __future__ import annotations

import numpy as np

from physics.store import CIRCLE
from physics.views import RenderData
from physics.views import fixture_rows, joint_rows  # plain numpy: no kernel


def render_data(world) -> RenderData:
    """The world's render data (same fields as ``world.render_data()``), without kernels: every
    fixture's vertices and circle centre in world coordinates, fixture and body AABBs."""
    st = world._store
    n = st.bodies.n
    B = st.bodies.view
    F = st.fixtures.view
    nf = st.fixtures.n
    V = st.verts.view
    top = st.verts.top
    fb = F.body[:nf].astype(np.int64)
    body_of = np.repeat(fb, F.vcount[:nf])
    rows = np.concatenate([np.arange(s, s + c) for s, c in zip(F.vstart[:nf], F.vcount[:nf])]) \
        if nf else np.zeros(0, np.int64)
    verts = np.zeros((top, 2))
    if len(rows):
        q = B.q[body_of]
        c, s = np.cos(q), np.sin(q)
        loc = V.local[rows]
        verts[rows, 0] = B.x[body_of, 0] + c * loc[:, 0] - s * loc[:, 1]
        verts[rows, 1] = B.x[body_of, 1] + s * loc[:, 0] + c * loc[:, 1]
    fixtures = fixture_rows(st)
    half = 0.5 * world.speculative_distance
    aabb = np.tile(np.array([np.inf, np.inf, -np.inf, -np.inf]), (n, 1))
    for f in range(nf):
        i, r = fb[f], F.radius[f]
        if F.shape[f] == CIRCLE:
            q = B.q[i]
            c, s = np.cos(q), np.sin(q)
            lx, ly = F.center[f]
            centre = B.x[i] + (c * lx - s * ly, s * lx + c * ly)
            fixtures["center"][f] = centre
            lo, hi = centre - r, centre + r
        else:
            v = verts[F.vstart[f]:F.vstart[f] + F.vcount[f]]
            lo, hi = v.min(0) - r, v.max(0) + r
        aabb[i, :2] = np.minimum(aabb[i, :2], lo - half)
        aabb[i, 2:] = np.maximum(aabb[i, 2:], hi + half)
    ends = _spring_ends(B, st.springs.view, st.springs.n)
    return RenderData(verts, B.vstart[:n], B.vcount[:n], B.kind[:n], B.awake[:n], B.shape[:n], B.radius[:n],
                      B.x[:n], B.q[:n], B.com[:n], B.id[:n], aabb, ends, np.zeros((0, 2)), np.zeros((0, 2)),
                      joint_rows(st), fixtures)


def _spring_ends(B, S, ns):
    ends = np.zeros((ns, 2, 2))
    if not ns:
        return ends

    def anchor(slots, local):
        q = B.q[slots]
        c, s = np.cos(q), np.sin(q)
        return B.x[slots] + np.stack([c * local[:, 0] - s * local[:, 1], s * local[:, 0] + c * local[:, 1]], 1)

    ends[:, 0] = anchor(S.a[:ns], S.la[:ns])
    ends[:, 1] = np.where((S.b[:ns] < 0)[:, None], S.lb[:ns], anchor(np.maximum(S.b[:ns], 0), S.lb[:ns]))
    return ends


def hold(world) -> None:
    """Until the kernels are loaded, ``world.render_data()`` answers from numpy.  Picking, hover,
    the selection's handles and framing (F) all ask the world for its render data; its kernel
    would compile in the window's thread on a cold cache (seconds of a frozen window, and the
    compiler's lock taken from the warmup).  An instance attribute shadows the method, so every
    caller gets the preview without knowing about it; ``release`` restores the kernel."""
    if "render_data" not in vars(world):
        world.render_data = lambda: render_data(world)


def release(world) -> None:
    vars(world).pop("render_data", None)
