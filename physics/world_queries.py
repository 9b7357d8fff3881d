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
        p, e = finite_vec(start, "start"), finite_vec(end, "end")
        cat, msk = _bits(category, mask)
        qs = query_state(self)
        F = self._store.fixtures.view
        d = e - p
        m = cast_one(F, qs.wv, qs.wn, qs.wc, qs.nb, qs.info, qs.order, p[0], p[1], d[0], d[1], bool(first),
                     cat, msk, qs.slots, qs.ts, qs.ns)
        slots, ts, ns = qs.slots[:m], qs.ts[:m], qs.ns[:m]
        idx = np.lexsort((slots, ts))
        out = []
        for k in idx:
            fx = self._fixtures_of([slots[k]])[0]
            t = float(ts[k])
            out.append(RayHit(fx, fx.body, (float(p[0] + t * d[0]), float(p[1] + t * d[1])),
                              (float(ns[k, 0]), float(ns[k, 1])), t))
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
        cast_many(F, qs.wv, qs.wn, qs.wc, qs.nb, qs.info, qs.order, s, e, cat, msk, slot, t, out["normal"])
        hit = slot >= 0
        out["fraction"] = t
        out["fixture"] = np.where(hit, F.id[np.maximum(slot, 0)] if st.fixtures.n else -1, -1)
        bodies = st.bodies.view.id[F.body[np.maximum(slot, 0)]] if st.fixtures.n else -1
        out["body"] = np.where(hit, bodies, -1)
        out["point"] = np.where(hit[:, None], s + t[:, None] * (e - s), 0.0)
        return out

    def _overlap_slots(self, P, r, category, mask) -> np.ndarray:
        cat, msk = _bits(category, mask)
        qs = query_state(self)
        m = overlapping(self._store.fixtures.view, qs.wv, qs.wc, qs.box, qs.nb, qs.info, qs.order, P, r,
                        cat, msk, qs.slots)
        return qs.slots[:m]

    def query_aabb(self, lower, upper, category=0x1, mask=0xFFFF) -> list:
        """Fixtures whose shapes overlap the box from ``lower`` to ``upper`` (m; exact shapes, not
        their boxes; touching counts), in table order.  ValueError for a non-finite or inverted box."""
        lo, hi = finite_vec(lower, "lower"), finite_vec(upper, "upper")
        if np.any(hi < lo):
            raise ValueError(f"upper: must be >= lower in x and y, got lower {lo.tolist()} upper {hi.tolist()}")
        P = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
        if np.any(hi == lo):  # a flat box is a segment or a point (a 4-gon of zero area is not convex)
            P = np.unique(P, axis=0)
        return self._fixtures_of(self._overlap_slots(P, 0.0, category, mask))

    def query_point_all(self, point, category=0x1, mask=0xFFFF) -> list:
        """Every fixture containing world ``point`` (boundary included), in table order
        (World.query_point returns only the topmost body).  ValueError for a non-finite point."""
        P = finite_vec(point, "point").reshape(1, 2)
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
        f = _shape_cast(self._store.fixtures.view, qs.wv, qs.wc, qs.box, qs.nb, qs.info, qs.order, P, r,
                        T[0], T[1], cat, msk, qs.slots, hit)
        if f < 0:
            return None
        fx = self._fixtures_of([f])[0]
        return ShapeHit(fx, fx.body, float(hit[0]), (float(hit[1]), float(hit[2])), (float(hit[3]), float(hit[4])))
