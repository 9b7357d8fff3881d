"""Read-only views of a world: its state, its touching contacts, arrays for drawing, point queries."""
from __future__ import annotations

from collections import namedtuple

import numpy as np

from .store import CIRCLE
from .store.contacts import PAIR_LOW
from .store.joints import BROKEN

STATE_DTYPE = np.dtype([("id", np.int64), ("position", np.float64, (2,)), ("angle", np.float64),
                        ("velocity", np.float64, (2,)), ("angular_velocity", np.float64), ("awake", np.bool_)])

Contact = namedtuple("Contact", "body_a body_b points normal depth fixture_a fixture_b normal_impulses tangent_impulses",
                     defaults=(None, None, None, None))
Contact.__doc__ = """A touching contact of the last step (``world.contacts()``).

``points`` are the kept manifold points (world, m), ``normal`` the unit normal from body_a to
body_b, ``depth`` the deepest penetration (m).  ``normal_impulses`` and ``tangent_impulses``
are, per kept point, the impulse (N s) the contact applied to body_b over the last step (body_a
gets the opposite), along ``normal`` and along the tangent (-n_y, n_x).  What they are per
solver mode (docs/solver-modes.md): ``sequential_impulse`` and ``impulse`` / ``hybrid`` their
accumulated impulses of the step; ``soft_step`` the last sub-step's accumulated impulse times
the sub-steps (the step's impulse under a steady load); ``penalty`` (and hybrid's penalty
points) the force times the sub-step length, summed over the sub-steps."""
RenderData = namedtuple(
    "RenderData",
    "vertices vstart vcount kind awake shape radius center angle com ids aabb "
    "spring_ends contact_points contact_normals joints fixtures", defaults=(None, None))

#: one row per fixture for drawing (RenderData.fixtures): its id, body slot, shape code
#: (store/fixtures.py), radius, core vertices in RenderData.vertices (vstart, vcount) and a
#: circle's world centre, and whether it is a sensor
FIXTURE_DRAW_DTYPE = np.dtype([("id", np.int64), ("body", np.int32), ("shape", np.int8), ("radius", np.float64),
                               ("vstart", np.int32), ("vcount", np.int32), ("center", np.float64, (2,)),
                               ("sensor", np.bool_)])

#: one row per joint for drawing (RenderData.joints): its id and kind code (store/joints.py
#: JOINT_KINDS), world anchors on a and b (b's is the world point for a world joint), the axis
#: in world coordinates (prismatic, wheel), the limits (NaN: none), whether it is broken
JOINT_DRAW_DTYPE = np.dtype([("id", np.int64), ("kind", np.int8), ("anchor_a", np.float64, (2,)),
                             ("anchor_b", np.float64, (2,)), ("axis", np.float64, (2,)),
                             ("lower", np.float64), ("upper", np.float64), ("broken", np.bool_)])


def state(world) -> np.ndarray:
    """Every body's state as a read-only structured array (STATE_DTYPE), in body order."""
    n = world._store.bodies.n
    B = world._store.bodies.view
    out = np.zeros(n, STATE_DTYPE)
    q = B.q[:n]
    c, s = np.cos(q), np.sin(q)
    com = B.com[:n]
    out["id"] = B.id[:n]
    out["position"][:, 0] = B.x[:n, 0] - (c * com[:, 0] - s * com[:, 1])
    out["position"][:, 1] = B.x[:n, 1] - (s * com[:, 0] + c * com[:, 1])
    out["angle"] = q
    out["velocity"] = B.v[:n]
    out["angular_velocity"] = B.w[:n]
    out["awake"] = B.awake[:n] != 0
    out.setflags(write=False)
    return out


def impulse_scale(world) -> float:
    """Factor from the contact table's impulses to impulses over the last step: the step length
    over the span the last solve recorded (soft_step: one sub-step), 1 for modes that record none
    (their impulses are the step's already)."""
    c = world._store.contacts
    if c.span_step != world.steps or c.span <= 0.0:
        return 1.0
    return float(world._pipeline.ctx.get("dt")) / c.span


def _touching(world) -> np.ndarray:
    """(rows, 2) bool: which points of each contact row of the last step touch (depth > -slop);
    the one rule ``contacts()`` and ``contact_depths()`` report by."""
    c = world._store.contacts
    d = c.cur.depth[:c.n]
    live = np.arange(d.shape[1])[None, :] < c.cur.count[:c.n, None]
    return live & (d > -world.linear_slop)


def contacts(world) -> list:
    """Touching contacts of the last step (normal from body_a to body_b, depth > -slop)."""
    c = world._store.contacts
    scale = impulse_scale(world)
    out = []
    ids = world._store.bodies.view.id
    fixtures = world._fixture_handles
    touch = _touching(world)
    for k in np.flatnonzero(touch.any(axis=1)):
        keep = np.flatnonzero(touch[k]).tolist()
        key = int(c.cur.key[k])  # (fixture id a << 32) | fixture id b (narrowphase/kernel.py)
        out.append(Contact(world._handles[int(ids[c.cur.a[k]])], world._handles[int(ids[c.cur.b[k]])],
                           [tuple(map(float, c.cur.point[k, p])) for p in keep],
                           tuple(map(float, c.cur.normal[k])),
                           max(float(c.cur.depth[k, p]) for p in keep),
                           fixtures.get(key >> 32), fixtures.get(key & PAIR_LOW),
                           tuple(float(c.cur.jn[k, p]) * scale for p in keep),
                           tuple(float(c.cur.jt[k, p]) * scale for p in keep)))
    return out


def contact_depths(world) -> np.ndarray:
    """The depth (m) of each touching contact of the last step, as ``contacts()`` reports it
    (the deepest point of each row with depth > -slop), without building a Python object per
    contact: numpy over the contact table, for per-frame readouts of large worlds."""
    touch = _touching(world)
    d = np.where(touch, world._store.contacts.cur.depth[:len(touch)], -np.inf)
    return d.max(axis=1)[touch.any(axis=1)]


def query_point(world, p):
    """The topmost (last added) body one of whose fixtures contains world point ``p``, or None."""
    st = world._store
    B = st.bodies.view
    F = st.fixtures.view
    world._pipeline.refresh_geometry(world)
    box = F.aabb[: st.fixtures.n]
    cand = np.nonzero((box[:, 0] <= p[0]) & (p[0] <= box[:, 2]) & (box[:, 1] <= p[1]) & (p[1] <= box[:, 3]))[0]
    V = st.verts.view
    best = None
    for f in cand:
        s = int(F.body[f])
        if best is not None and s < best:
            continue
        if _contains(F, V, f, p):
            best = s
    return None if best is None else world._handles[int(B.id[best])]


def _contains(F, V, f, p) -> bool:
    """Is world point ``p`` inside fixture f (a rounded core reaches its radius further)?"""
    r = float(F.radius[f])
    if F.shape[f] == CIRCLE:
        return bool(np.hypot(*(p - F.wcenter[f])) <= r)
    a, k = int(F.vstart[f]), int(F.vcount[f])
    pts = V.world[a:a + k]
    if k >= 3 and np.all(np.einsum("ij,ij->i", p - pts, V.wnormal[a:a + k]) <= 0):
        return True
    if r <= 0.0:
        return False
    for i in range(k):  # within r of an edge of the core
        e = pts[(i + 1) % k] - pts[i]
        t = np.clip(np.dot(p - pts[i], e) / max(np.dot(e, e), 1e-300), 0.0, 1.0)
        if np.hypot(*(p - pts[i] - t * e)) <= r:
            return True
    return False


def render_data(world) -> RenderData:
    """Arrays for drawing (views into the world's state: read, do not write)."""
    world._pipeline.refresh_geometry(world)
    st = world._store
    n = st.bodies.n
    B = st.bodies.view
    V = st.verts.view
    S = st.springs.view
    ns = st.springs.n
    ends = np.zeros((ns, 2, 2))
    if ns:
        ends[:, 0] = _anchor_world(B, S.a[:ns], S.la[:ns])
        world_b = S.b[:ns] < 0
        ends[:, 1] = np.where(world_b[:, None], S.lb[:ns],
                              _anchor_world(B, np.maximum(S.b[:ns], 0), S.lb[:ns]))
    c = st.contacts
    cnt = c.cur.count[: c.n].astype(np.int64)
    mask = np.arange(2)[None, :] < cnt[:, None]
    pts = c.cur.point[: c.n][mask]
    nrm = np.repeat(c.cur.normal[: c.n], cnt, axis=0)
    return RenderData(V.world[: st.verts.top], B.vstart[:n], B.vcount[:n], B.kind[:n], B.awake[:n],
                      B.shape[:n], B.radius[:n], B.x[:n], B.q[:n], B.com[:n], B.id[:n], B.aabb[:n],
                      ends, pts, nrm, joint_rows(st), fixture_rows(st))


def fixture_rows(st) -> np.ndarray:
    """RenderData.fixtures (FIXTURE_DRAW_DTYPE) for the store's fixtures."""
    nf = st.fixtures.n
    F = st.fixtures.view
    out = np.zeros(nf, FIXTURE_DRAW_DTYPE)
    for name in ("id", "body", "shape", "radius", "vstart", "vcount"):
        out[name] = getattr(F, name)[:nf]
    out["center"] = F.wcenter[:nf]
    out["sensor"] = F.sensor[:nf] != 0
    return out


def joint_rows(st) -> np.ndarray:
    """RenderData.joints (JOINT_DRAW_DTYPE) for the store's joints."""
    nj = st.joints.n
    out = np.zeros(nj, JOINT_DRAW_DTYPE)
    if not nj:
        return out
    B = st.bodies.view
    J = st.joints.view
    out["id"] = J.id[:nj]
    out["kind"] = J.kind[:nj]
    out["anchor_a"] = _anchor_world(B, J.a[:nj], J.la[:nj])
    world_b = J.b[:nj] < 0
    out["anchor_b"] = np.where(world_b[:, None], J.lb[:nj], _anchor_world(B, np.maximum(J.b[:nj], 0), J.lb[:nj]))
    q = B.q[J.a[:nj]]
    c, s = np.cos(q), np.sin(q)
    ax = J.axis[:nj]
    out["axis"][:, 0] = c * ax[:, 0] - s * ax[:, 1]
    out["axis"][:, 1] = s * ax[:, 0] + c * ax[:, 1]
    out["lower"] = J.lower[:nj]
    out["upper"] = J.upper[:nj]
    out["broken"] = (J.flags[:nj] & BROKEN) != 0
    return out


def _anchor_world(B, slots, local):
    q = B.q[slots]
    c, s = np.cos(q), np.sin(q)
    return B.x[slots] + np.stack([c * local[:, 0] - s * local[:, 1], s * local[:, 0] + c * local[:, 1]], 1)
