"""World's spatial queries: ray casts, box, point and shape overlap, shape casts (a part of World).

Thin Python over the compiled walks of physics/queries/: validate, run the kernel on the
cached query state (queries/cache.py), turn slots into handles.  Every query sees the bodies
where they are now and filters like a fixture: a fixture is seen when ``fixture.category &
mask`` and ``fixture.mask & category`` are both non-zero (Box2D v3's query filter).
"""
from __future__ import annotations

import numpy as np

from .fixture import filter_bits
from .queries.cache import query_state
from .queries.hits import RAY_DTYPE, RayHit, ShapeHit
from .queries.overlap import overlapping
from .queries.placed import placed_core
from .queries.ray import cast_many, cast_one
from .queries.shape_cast import shape_cast as _shape_cast
from .validate import finite_vec

_U64 = np.uint64


def _bits(category, mask):
    return _U64(filter_bits(category, "category")), _U64(filter_bits(mask, "mask"))


_DEFAULT_BITS = _bits(0x1, 0xFFFF)
_PLAIN = (float, int)  # exact types: bool and numpy scalars take the checked path
_BIG = 1.7e308  # below float max, so the comparisons reject inf, nan and ints beyond float range


def _filter(category, mask):
    """The query's filter bits; the default filter skips the checks (it is valid by construction)."""
    if type(category) is int and type(mask) is int and category == 0x1 and mask == 0xFFFF:
        return _DEFAULT_BITS
    return _bits(category, mask)


def _pair(value, field: str) -> tuple:
    """``value`` as two finite floats; plain tuples of floats take a fast path (a game's rays call
    this per ray), anything else goes through validate.finite_vec and its errors."""
    if (type(value) is tuple or type(value) is list) and len(value) == 2:
        x, y = value
        if type(x) in _PLAIN and type(y) in _PLAIN and -_BIG < x < _BIG and -_BIG < y < _BIG:
            return float(x), float(y)  # finite, and an int this small converts exactly enough
    v = finite_vec(value, field)
    return float(v[0]), float(v[1])


def _points(value, field: str) -> np.ndarray:
    """An (n, 2) array of finite numbers, or ValueError naming ``field`` and the first bad row."""
    a = np.asarray(value, dtype=np.float64)
    if a.ndim != 2 or a.shape[1] != 2:
        raise ValueError(f"{field}: expected an (n, 2) array of points, got shape {a.shape}")
    bad = np.nonzero(~np.isfinite(a).all(axis=1))[0]
    if len(bad):
        raise ValueError(f"{field}[{int(bad[0])}]: must be finite, got {a[bad[0]].tolist()}")
    return np.ascontiguousarray(a)


class QueriesMixin:
    """The query half of :class:`~physics.World` (see world.py for the state it uses)."""

    def _fixtures_of(self, slots) -> list:
        ids = self._store.fixtures.view.id
        return [self._fixture_handles[int(ids[f])] for f in slots]

    def ray_cast(self, start, end, first: bool = False, category=0x1, mask=0xFFFF) -> list:
        """Fixtures hit by the segment from ``start`` to ``end`` (m), as a list of physics.RayHit,
        nearest first (ties by fixture order); ``first=True`` returns only the nearest.

        A ray starting inside a shape hits it at fraction 0 with normal (0, 0); chain segments are
        one-sided (a ray from behind passes).  ``category``/``mask`` filter like a fixture's.
        ValueError for a non-finite point or bad filter bits.
        """
        px, py = _pair(start, "start")
        ex, ey = _pair(end, "end")
        cat, msk = _filter(category, mask)
        qs = query_state(self)
        dx, dy = ex - px, ey - py
        m = cast_one(qs.qf, qs.wv, qs.wn, qs.wc, qs.nb, qs.info, qs.order, px, py, dx, dy, bool(first),
                     cat, msk, qs.slots, qs.ts, qs.ns)
        if m == 0:
            return []
        order = range(1) if m == 1 else np.lexsort((qs.slots[:m], qs.ts[:m]))
        out = []
        for k in order:
            fx = self._fixtures_of([qs.slots[k]])[0]
            t = float(qs.ts[k])
            out.append(RayHit(fx, fx.body, (px + t * dx, py + t * dy), (float(qs.ns[k, 0]), float(qs.ns[k, 1])), t))
        return out

    def ray_cast_many(self, starts, ends, category=0x1, mask=0xFFFF) -> np.ndarray:
        """The nearest hit of each ray ``starts[i] -> ends[i]`` ((n, 2) arrays, m) as a structured
        array of physics.queries.hits.RAY_DTYPE: fixture and body ids, point, normal, fraction;
        a miss has ids -1 and fraction -1.  ValueError (naming the row) for a non-finite point."""
        s, e = _points(starts, "starts"), _points(ends, "ends")
        if s.shape != e.shape:
            raise ValueError(f"ends: expected the shape of starts {s.shape}, got {e.shape}")
        cat, msk = _bits(category, mask)
        qs = query_state(self)
        st = self._store
        F = st.fixtures.view
        n = len(s)
        slot = np.empty(n, np.int32)
        t = np.empty(n)
        out = np.zeros(n, RAY_DTYPE)
        cast_many(qs.qf, qs.wv, qs.wn, qs.wc, qs.nb, qs.info, qs.order, s, e, cat, msk, slot, t, out["normal"])
        hit = slot >= 0
        out["fraction"] = t
        out["fixture"] = np.where(hit, F.id[np.maximum(slot, 0)] if st.fixtures.n else -1, -1)
        bodies = st.bodies.view.id[F.body[np.maximum(slot, 0)]] if st.fixtures.n else -1
        out["body"] = np.where(hit, bodies, -1)
        out["point"] = np.where(hit[:, None], s + t[:, None] * (e - s), 0.0)
        return out

    def _overlap_slots(self, P, r, category, mask) -> np.ndarray:
        cat, msk = _filter(category, mask)
        qs = query_state(self)
        m = overlapping(qs.qf, qs.wv, qs.wc, qs.box, qs.nb, qs.info, qs.order, P, r,
                        cat, msk, qs.slots)
        return qs.slots[:m]

    def query_aabb(self, lower, upper, category=0x1, mask=0xFFFF) -> list:
        """Fixtures whose shapes overlap the box from ``lower`` to ``upper`` (m; exact shapes, not
        their boxes; touching counts), in table order.  ValueError for a non-finite or inverted box."""
        (x0, y0), (x1, y1) = _pair(lower, "lower"), _pair(upper, "upper")
        if x1 < x0 or y1 < y0:
            raise ValueError(f"upper: must be >= lower in x and y, got lower {[x0, y0]} upper {[x1, y1]}")
        P = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
        if x1 == x0 or y1 == y0:  # a flat box is a segment or a point (a 4-gon of zero area is not convex)
            P = np.unique(P, axis=0)
        return self._fixtures_of(self._overlap_slots(P, 0.0, category, mask))

    def query_point_all(self, point, category=0x1, mask=0xFFFF) -> list:
        """Every fixture containing world ``point`` (boundary included), in table order
        (World.query_point returns only the topmost body).  ValueError for a non-finite point."""
        P = np.array([_pair(point, "point")])
        return self._fixtures_of(self._overlap_slots(P, 0.0, category, mask))

    def overlap(self, shape, position=(0.0, 0.0), angle: float = 0.0, category=0x1, mask=0xFFFF) -> list:
        """Fixtures overlapping ``shape`` (a Polygon, Circle, Capsule or Segment) placed at
        ``position`` turned by ``angle`` (rad), touching included, in table order."""
        P, r = placed_core(shape, position, angle)
        return self._fixtures_of(self._overlap_slots(P, r, category, mask))

    def shape_cast(self, shape, position, angle, translation, category=0x1, mask=0xFFFF):
        """The first fixture that ``shape`` placed at ``position``/``angle`` meets when moved by
        ``translation`` (m), as a physics.ShapeHit (fraction, point on the fixture, normal toward
        the shape), or None.  A shape starting in contact hits at fraction 0 with normal (0, 0)."""
        P, r = placed_core(shape, position, angle)
        T = finite_vec(translation, "translation")
        cat, msk = _bits(category, mask)
        qs = query_state(self)
        hit = np.empty(5)
        f = _shape_cast(qs.qf, qs.wv, qs.wc, qs.box, qs.nb, qs.info, qs.order, P, r,
                        T[0], T[1], cat, msk, qs.slots, hit)
        if f < 0:
            return None
        fx = self._fixtures_of([f])[0]
        return ShapeHit(fx, fx.body, float(hit[0]), (float(hit[1]), float(hit[2])), (float(hit[3]), float(hit[4])))
