"""The whole narrow-phase pass (``physics.collision.narrowphase.collide``) on hand-built states.

States are filled by hand (Table + FixtureTable + VertexPool + update_geometry) so these
tests depend only on the store layout, not on the World class (one fixture per body: the
fixture slots are the body slots).
"""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from physics.options import NARROWPHASES
from physics.step.context import StepContext
from physics.store import CARRIED, ContactBuffer
from physics.geometry.transform import update_geometry
from physics.collision.narrowphase import collide
from physics.geometry.shapes import Polygon
from physics.store import BODY_FIELDS, CIRCLE, POLYGON, STATIC, Bodies, FixtureTable, Table, VertexPool
from physics.store.fixtures import ALL_BITS
from physics.store.slot_list import ALL

DT, SPEC = 1 / 60, 0.02


class State:
    """Bodies + vertices + contacts; ``add`` returns the slot."""

    def __init__(self):
        self.bodies = Table(BODY_FIELDS, Bodies)
        self.fixtures = FixtureTable()
        self.verts = VertexPool()
        self.contacts = ContactBuffer(cap=4)

    def add(self, shape, pos, angle=0.0, vel=(0.0, 0.0), w=0.0, e=0.2, mu=(0.6, 0.4), static=False):
        _, s = self.bodies.add()
        a = self.bodies.arrays
        if isinstance(shape, float):
            a["shape"][s], a["radius"][s], a["bound_r"][s] = CIRCLE, shape, shape
        else:
            local = shape.vertices - shape.centroid
            start = self.verts.add(local)
            a = self.bodies.arrays
            a["shape"][s], a["vstart"][s], a["vcount"][s] = POLYGON, start, len(local)
            a["bound_r"][s] = np.hypot(local[:, 0], local[:, 1]).max()
        a["x"][s], a["q"][s], a["v"][s], a["w"][s] = pos, angle, vel, w
        a["e"][s], a["mu_s"][s], a["mu_d"][s] = e, mu[0], mu[1]
        a["kind"][s] = STATIC if static else 0
        _, f = self.fixtures.add()
        F = self.fixtures.arrays
        F["body"][f] = s
        for k in ("shape", "radius", "vstart", "vcount", "e", "mu_s", "mu_d"):
            F[k][f] = a[k][s]
        F["category"][f], F["mask"][f] = 1, ALL_BITS
        return s

    def move(self, s, pos, angle=None):
        self.bodies.arrays["x"][s] = pos
        if angle is not None:
            self.bodies.arrays["q"][s] = angle

    def collide(self, pairs, method="sat"):
        B, F, V = self.bodies.view, self.fixtures.view, self.verts.view
        update_geometry(B, F, V, self.bodies.n, self.fixtures.n, DT, SPEC, True, None, ALL,
                        self.fixtures.n)
        pairs = np.array(pairs, dtype=np.int32).reshape(-1, 2)
        ctx = StepContext()
        ctx.set("dt", DT)
        ctx.set("spec", SPEC)
        ctx.set("narrowphase", NARROWPHASES.index(method))
        n = collide(ctx, self.bodies.arrays, self.fixtures.arrays, self.verts.arrays, pairs, len(pairs), self.contacts)
        return self.contacts.cur, n


def ground_and_box(w=1.0, h=1.0, depth=0.01, x=0.0, origin=(0.0, 0.0), scale=1.0):
    s = State()
    ox, oy = origin
    g = s.add(Polygon.box(4 * scale, scale), (ox, oy - 0.5 * scale), static=True)
    b = s.add(Polygon.box(w * scale, h * scale), (ox + x * scale, oy + (0.5 * h - depth) * scale))
    return s, g, b


# -- resting box: two points, right normal and depth, stable features -------------
@pytest.mark.parametrize("method", ["sat", "gjk"])
def test_box_resting_flat_gets_two_points(method):
    s, g, b = ground_and_box(depth=0.01)
    C, n = s.collide([(g, b)], method)
    assert n == 1 and C.count[0] == 2
    assert C.normal[0] == pytest.approx((0.0, 1.0), abs=1e-12)
    assert C.depth[0] == pytest.approx((0.01, 0.01), abs=1e-12)
    # points midway between the surfaces, at the box's bottom corners
    assert sorted(C.point[0, :, 0]) == pytest.approx([-0.5, 0.5])
    assert C.point[0, :, 1] == pytest.approx([-0.005, -0.005])
    feats = set(C.feature[0])
    for dx, da in ((0.01, 0.0), (-0.02, 0.001), (0.0, -0.002)):
        s.move(b, (dx, 0.49), da)
        C, n = s.collide([(g, b)], method)
        assert n == 1 and C.count[0] == 2 and set(C.feature[0]) == feats


def test_sat_and_gjk_give_the_same_rows():
    rng = np.random.default_rng(7)
    s = State()
    shapes = [Polygon.box(1, 1), Polygon.regular(5, 0.6), Polygon.box(2, 0.2), 0.4, 0.25]
    for k in range(40):
        s.add(shapes[k % len(shapes)], rng.uniform(-3, 3, 2), rng.uniform(0, 2 * math.pi))
    pairs = [(i, j) for i in range(40) for j in range(i + 1, 40)]
    C1, n1 = s.collide(pairs, "sat")
    rows1 = {int(C1.key[k]): (C1.count[k], C1.normal[k].copy(), C1.depth[k].copy()) for k in range(n1)}
    C2, n2 = s.collide(pairs, "gjk")
    deep = 0
    for k in range(n2):
        c, nrm, d = rows1[int(C2.key[k])]
        if d[:c].max() > 0:  # overlapping: the same face by either method
            deep += 1
            assert C2.count[k] == c
            assert C2.normal[k] == pytest.approx(nrm, abs=1e-9)
            assert C2.depth[k, :c] == pytest.approx(d[:c], abs=1e-9)
    assert deep > 10
    # speculative rows: GJK's exact distance drops some pairs SAT keeps, never the reverse
    assert set(int(k) for k in C2.key[:n2]) <= set(rows1)


def test_rows_sorted_by_key_oriented_by_id_with_materials():
    s = State()
    a = s.add(Polygon.box(1, 1), (0, 0), e=0.1, mu=(0.4, 0.3))
    b = s.add(Polygon.box(1, 1), (0.9, 0), e=0.7, mu=(0.9, 0.6))
    c = s.add(0.5, (0.45, 0.95), e=0.3, mu=(0.25, 0.25))
    C, n = s.collide([(c, a), (b, a), (b, c)])  # slots listed in any order
    assert n == 3
    ids = s.bodies.arrays["id"]
    keys = C.key[:n]
    assert (np.diff(keys) > 0).all()
    for k in range(n):
        ia, ib = ids[C.a[k]], ids[C.b[k]]
        assert ia < ib and C.key[k] == (ia << 32) | ib
        # the normal points from a to b
        d = s.bodies.arrays["x"][C.b[k]] - s.bodies.arrays["x"][C.a[k]]
        assert float(C.normal[k] @ d) > 0
    k = list(keys).index((ids[a] << 32) | ids[b])
    assert C.e[k] == 0.7
    assert C.mu_s[k] == pytest.approx(math.sqrt(0.4 * 0.9))
    assert C.mu_d[k] == pytest.approx(math.sqrt(0.3 * 0.6))
    # a new pair carries no state over from a previous step (store/contacts.py CARRIED)
    assert not any(getattr(C, f)[:n].any() for f in CARRIED)


# -- warm starting --------------------------------------------------------------------
def test_warm_start_copies_matched_features_and_zeroes_others():
    s, g, b = ground_and_box(depth=0.01)
    c = s.add(0.3, (3.0, 5.0))                 # far away: no row
    C, n = s.collide([(g, b), (g, c)])
    assert n == 1
    C.jn[0] = (1.5, 2.5)
    C.jt[0] = (-0.5, 0.25)
    f0 = C.feature[0].copy()
    s.move(b, (0.003, 0.49))                   # same features
    C, n = s.collide([(g, b), (g, c)])
    assert n == 1
    for p in range(2):
        q = list(f0).index(C.feature[0, p])
        assert C.jn[0, p] == (1.5, 2.5)[q] and C.jt[0, p] == (-0.5, 0.25)[q]
    # slide the box past the ground's right end: its right point is now the box's edge clipped
    # at the ground's side plane, the same contact as the corner it was (manifold.py's ids name
    # the vertex pair, as Box2D v3's do): both points keep their impulses
    C.jn[0] = (1.0, 2.0)
    C.jt[0] = (0.5, 0.25)
    f1 = C.feature[0].copy()
    s.move(b, (2.0, 0.49))
    C, n = s.collide([(g, b), (g, c)])
    assert n == 1 and C.count[0] == 2
    assert set(C.feature[0]) == set(f1)
    for p in range(2):
        q = list(f1).index(C.feature[0, p])
        assert C.jn[0, p] == (1.0, 2.0)[q] and C.jt[0, p] == (0.5, 0.25)[q]
    # a quarter turn: other vertices of the box touch, so nothing is carried
    C.jn[0] = (1.0, 1.0)
    C.jt[0] = (1.0, 1.0)
    f2 = C.feature[0].copy()
    s.move(b, (2.0, 0.49), angle=0.5 * math.pi)
    C, n = s.collide([(g, b), (g, c)])
    assert n == 1 and C.count[0] == 2
    assert not set(C.feature[0]) & set(f2)
    assert (C.jn[0] == 0.0).all() and (C.jt[0] == 0.0).all()
    # a new pair has nothing to inherit
    s.move(c, (0.0, 0.0 + 0.29))
    C, n = s.collide([(g, b), (g, c)])
    k = list(C.key[:n]).index((s.bodies.arrays["id"][g] << 32) | s.bodies.arrays["id"][c])
    assert C.jn[k, 0] == 0.0 and C.jt[k, 0] == 0.0


# -- speculative contacts ----------------------------------------------------------------
def test_speculative_rows_only_when_closing_fast():
    s = State()
    a = s.add(Polygon.box(1, 1), (0, 0), static=True)
    b = s.add(Polygon.box(1, 1), (0, 1.1))       # 0.1 apart
    C, n = s.collide([(a, b)])
    assert n == 0
    s.bodies.arrays["v"][b] = (0.0, -9.0)        # margin = 0.02 + 9/60 = 0.17
    for method in ("sat", "gjk"):
        C, n = s.collide([(a, b)], method)
        assert n == 1 and C.count[0] == 2
        assert C.depth[0] == pytest.approx((-0.1, -0.1))
        assert C.normal[0] == pytest.approx((0.0, 1.0))


# -- robustness: scales, far from the origin, slivers, many vertices, degenerate ------------
@pytest.mark.parametrize("scale", [0.01, 1.0, 100.0])
@pytest.mark.parametrize("far", [0.0, 1e4])
@pytest.mark.parametrize("method", ["sat", "gjk"])
def test_scale_and_distance_from_origin(scale, far, method):
    s, g, b = ground_and_box(depth=0.01, x=0.3, origin=(far, -far), scale=scale)
    C, n = s.collide([(g, b)], method)
    assert n == 1 and C.count[0] == 2
    assert C.normal[0] == pytest.approx((0.0, 1.0), abs=1e-9)
    # 1e-16 * 1e4 m of rounding in the stored positions is all that is lost
    assert C.depth[0] == pytest.approx((0.01 * scale,) * 2, rel=1e-6, abs=1e-11)


@pytest.mark.parametrize("method", ["sat", "gjk"])
def test_sliver_and_64_gon(method):
    s = State()
    g = s.add(Polygon.box(4, 1), (0, -0.5), static=True)
    sl = s.add(Polygon.box(1.0, 0.001), (0.2, 0.0004), angle=1e-4)
    big = s.add(Polygon.regular(64, 1.0), (0.0, 1.0 - 1e-3 + 0.001))
    C, n = s.collide([(g, sl), (sl, big), (g, big)], method)
    assert n >= 2
    for k in range(n):
        assert np.isfinite(C.normal[k]).all() and np.isfinite(C.point[k]).all()
        assert np.isfinite(C.depth[k]).all()
    k = list(C.b[:n]).index(sl) if sl in C.b[:n] else list(C.a[:n]).index(sl)
    assert C.count[k] == 2 and abs(C.normal[k, 1]) == pytest.approx(1.0, abs=1e-6)


@pytest.mark.parametrize("method", ["sat", "gjk"])
def test_degenerate_configurations_are_finite(method):
    s = State()
    a = s.add(Polygon.box(1, 1), (2.0, 2.0))
    b = s.add(Polygon.box(1, 1), (2.0, 2.0))           # exactly on top
    c = s.add(0.5, (2.0, 2.0))                         # circle centred on them
    d = s.add(0.5, (2.0, 2.0))                         # coincident circles
    C, n = s.collide([(a, b), (a, c), (c, d), (b, d)], method)
    assert n == 4
    for k in range(n):
        assert np.isfinite(C.normal[k]).all() and math.hypot(*C.normal[k]) == pytest.approx(1.0)
        assert np.isfinite(C.point[k, :C.count[k]]).all() and (C.depth[k, :C.count[k]] > 0).all()


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.floats(0.05, 1.0), st.floats(-np.pi, np.pi), st.floats(0.0, 1.6), st.floats(0, 2 * np.pi))
def test_polygon_circle_rows_either_order(r, q, d, phi):
    """A circle is a or b depending on ids; the row's normal always goes a -> b."""
    for circle_first in (True, False):
        s = State()
        pos_c = (d * math.cos(phi), d * math.sin(phi))
        if circle_first:
            c = s.add(r, pos_c)
            p = s.add(Polygon.box(1, 0.6), (0, 0), q)
        else:
            p = s.add(Polygon.box(1, 0.6), (0, 0), q)
            c = s.add(r, pos_c)
        C, n = s.collide([(p, c)])
        if n:
            a = C.a[0]
            sign = 1.0 if a == p else -1.0
            # the point is midway: the circle's surface is half a depth away along n
            ctr = np.array(pos_c)
            surf = C.point[0, 0] - sign * 0.5 * C.depth[0, 0] * C.normal[0]
            assert np.linalg.norm(surf - ctr) == pytest.approx(r, rel=1e-9)
            if np.linalg.norm(ctr) > 1e-6:
                assert float(sign * C.normal[0] @ ctr) > -1e-9


def test_many_box_pairs_in_one_call():
    """1000 overlapping box pairs in one call all get a 2-point row (throughput is in bench/collision.py)."""
    s = State()
    rng = np.random.default_rng(1)
    pairs = []
    for k in range(1000):
        x = 3.0 * k
        a = s.add(Polygon.box(1, 1), (x, 0), static=True)
        b = s.add(Polygon.box(1, 1), (x + rng.uniform(-0.3, 0.3), 0.99), rng.uniform(-0.05, 0.05))
        pairs.append((a, b))
    for method in ("sat", "gjk"):
        C, n = s.collide(pairs, method)
        assert n == 1000
        assert np.all(C.count[:n] >= 1)
        live = np.arange(2)[None, :] < C.count[:n, None]
        deepest = np.where(live, C.depth[:n], -np.inf).max(axis=1)
        assert np.all(deepest > 0)  # every row has a penetrating point


def _pile(full: bool):
    """A static floor, boxes of two sizes, a hexagon and circles falling into a pile."""
    import physics
    w = physics.World()
    w.add_body(Polygon.box(20, 1), kind="static", position=(0, -0.5))
    for k in range(6):
        w.add_body(Polygon.box(0.5 + 0.1 * k, 0.5), position=(0.3 * k - 0.8, 0.6 + 0.7 * k), angle=0.1 * k)
        w.add_body(physics.Circle(0.2), position=(0.25 * k - 0.5, 5.0 + 0.5 * k))
    w.add_body(Polygon.regular(6, 0.4), position=(0.1, 9.0))
    w._store.contacts.full = full
    return w


def test_the_lean_kernel_makes_the_rows_the_whole_one_makes():
    """SAT worlds of sharp polygons and circles collide in the lean kernel (compiled without GJK,
    EPA, rounded and chain pairs: kernel._manifold); its rows are the whole kernel's, bit for bit,
    so a pile falls the same way in both (positions after 2 s compared exactly)."""
    lean, whole = _pile(False), _pile(True)
    for _ in range(120):
        lean.step()
        whole.step()
    assert not lean._store.contacts.full and whole._store.contacts.full
    assert lean._store.contacts.n > 10
    for a, b in zip(lean.bodies, whole.bodies):
        assert a.position == b.position and a.angle == b.angle


def test_a_capsule_switches_the_world_to_the_whole_kernel():
    """The lean kernel leaves rounded and chain pairs out: the first step that meets one (a
    capsule dropped on the floor of a box world) runs the whole kernel instead, and so does every
    step after it; the capsule lands on the floor like a body in a world that had it from the
    start."""
    import physics
    w = _pile(False)
    w.sleeping = False     # the contacts of a body asleep are not listed
    for _ in range(10):
        w.step()
    assert not w._store.contacts.full
    cap = w.add_body(physics.Capsule((-0.5, 0.0), (0.5, 0.0), 0.2), position=(6.0, 0.5))
    ref = physics.World(sleeping=False)
    ref.add_body(Polygon.box(20, 1), kind="static", position=(0, -0.5))
    rcap = ref.add_body(physics.Capsule((-0.5, 0.0), (0.5, 0.0), 0.2), position=(6.0, 0.5))
    for _ in range(60):
        w.step()
        ref.step()
    assert w._store.contacts.full
    rows = [c for c in w.contacts() if cap in (c.body_a, c.body_b)]
    assert rows, "the capsule has no contact with the floor"
    # resting on the floor (surface at y = 0) at its radius, as in the reference world
    assert abs(cap.position[1] - 0.2) < 0.01 and abs(cap.position[1] - rcap.position[1]) < 1e-6
