"""Query and batch timings of issue 15 (a benchmark, not a timed test).

    python -m bench.queries [--bodies 10000] [--rays 10000]

Builds a world of ``--bodies`` bodies of mixed shapes (boxes, circles, capsules, rounded
polygons) scattered over a square of density ~0.25 bodies/m^2 and reports, best of
``--repeat`` runs after a warm-up (numba compiles on first use):

- ``ray_cast_many`` of ``--rays`` random rays of length 20 m (target < 50 ms), once with the
  query tree already built and once including its build after a step;
- one ``world.ray_cast(first=True)`` from Python (target < 20 us);
- ``query_aabb`` of a 2 m and a 20 m box, and of a 2 m box in a world a tenth the size (it scales
  with what it returns, not with the world);
- ``apply_impulses`` on every body.
"""
from __future__ import annotations

import argparse
import time

import numpy as np

import physics


def build(n: int, seed: int = 0) -> physics.World:
    rng = np.random.default_rng(seed)
    side = float(np.sqrt(n / 0.25))
    w = physics.World(gravity=(0, 0))
    shapes = [physics.Polygon.box(0.8, 0.5), physics.Circle(0.4), physics.Capsule((-0.3, 0), (0.3, 0), 0.2),
              physics.Polygon.regular(6, 0.4, corner_radius=0.05)]
    for i in range(n):
        w.add_body(shapes[i % len(shapes)], position=tuple(rng.uniform(0, side, 2)), angle=float(rng.uniform(-3, 3)))
    return w


def best(fn, repeat: int) -> float:
    out = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t)
    return min(out)


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bodies", type=int, default=10_000)
    ap.add_argument("--rays", type=int, default=10_000)
    ap.add_argument("--repeat", type=int, default=7)
    a = ap.parse_args(argv)
    w = build(a.bodies)
    rng = np.random.default_rng(1)
    side = float(np.sqrt(a.bodies / 0.25))
    S = rng.uniform(0, side, (a.rays, 2))
    ang = rng.uniform(0, 2 * np.pi, a.rays)
    E = S + 20.0 * np.stack([np.cos(ang), np.sin(ang)], axis=1)
    w.ray_cast_many(S[:10], E[:10])  # compile
    w.ray_cast((0, 0), (1, 1), first=True)
    w.query_aabb((0, 0), (1, 1))
    res = {}
    res["ray_cast_many_ms"] = 1e3 * best(lambda: w.ray_cast_many(S, E), a.repeat)
    ids = w.state()["id"]

    def rebuilt():
        w.apply_impulses(ids[:1], [[0.0, 0.0]])  # an edit: the tree is rebuilt by the next query
        w.ray_cast_many(S, E)
    res["ray_cast_many_with_rebuild_ms"] = 1e3 * best(rebuilt, a.repeat)
    w.ray_cast_many(S[:1], E[:1])
    k = 2000
    p0, p1 = S[:k].tolist(), E[:k].tolist()

    def singles():
        for p, e in zip(p0, p1):
            w.ray_cast(p, e, first=True)
    res["ray_cast_first_us"] = 1e6 * best(singles, a.repeat) / k
    c = side / 2
    for size in (2.0, 20.0):
        found = len(w.query_aabb((c, c), (c + size, c + size)))
        res[f"query_aabb_{size:g}m_us"] = 1e6 * best(lambda: w.query_aabb((c, c), (c + size, c + size)), a.repeat)
        res[f"query_aabb_{size:g}m_found"] = found
    small = build(a.bodies // 10)  # the same density, a tenth of the bodies: the box query should not care
    cs = float(np.sqrt(a.bodies // 10 / 0.25)) / 2
    small.query_aabb((cs, cs), (cs + 2.0, cs + 2.0))
    res["query_aabb_2m_tenth_world_us"] = 1e6 * best(lambda: small.query_aabb((cs, cs), (cs + 2.0, cs + 2.0)), a.repeat)
    J = np.zeros((len(ids), 2))
    res["apply_impulses_all_ms"] = 1e3 * best(lambda: w.apply_impulses(ids, J), a.repeat)
    print(f"{a.bodies} bodies, {a.rays} rays (best of {a.repeat})")
    for key, v in res.items():
        print(f"  {key:32s} {v:10.3f}" if isinstance(v, float) else f"  {key:32s} {v:10d}")
    return res


if __name__ == "__main__":
    main()
