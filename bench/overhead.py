"""Fixed costs of a step: an empty world, one body, a box on the ground (per mode), and the
cost of calling a compiled kernel from Python with the core's argument types."""
from __future__ import annotations

import time

import numpy as np


def _per_step(world, k):
    world.step()
    t = time.perf_counter()
    for _ in range(k):
        world.step()
    return 1e6 * (time.perf_counter() - t) / k


def overhead(modes, reps=20000) -> dict:
    """Microseconds per ``world.step()`` (best of three runs): ``empty_world_us``, and per mode
    ``one_body_us`` and ``box_on_ground_us``; ``kernel_call``: see ``call_overhead``."""
    import physics
    out = {"kernel_call": call_overhead(reps=reps // 4)}
    w = physics.World(sleeping=False)
    out["empty_world_us"] = min(_per_step(w, reps) for _ in range(3))
    out["one_body_us"], out["box_on_ground_us"] = {}, {}
    for m in modes:
        w = physics.World(solver=m, sleeping=False, gravity=(0, 0))
        w.add_body(physics.Polygon.box(1, 1), position=(0, 0))
        out["one_body_us"][m] = min(_per_step(w, reps // 10) for _ in range(3))
        w = physics.World(solver=m, sleeping=False, gravity=(0, -10))
        w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
        w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5))
        out["box_on_ground_us"][m] = min(_per_step(w, reps // 10) for _ in range(3))
    return out


def call_overhead(reps=20000):
    """Cost of calling a compiled kernel from Python with the core's argument types: one array, the
    bodies table (a namedtuple of arrays) and the contact table.  Numba unboxes every array of a
    namedtuple on every call, so each table argument costs microseconds before any work is done."""
    import physics
    from numba import njit

    @njit
    def touch(a, n):
        return n

    w = physics.World()
    w.add_body(physics.Polygon.box(1, 1))
    w.step()
    args = {"one array": w._bodies.view.x, "bodies table": w._bodies.view, "contacts table": w._contacts.cur,
            "springs table": w._springs.view, "vertex pool": w._verts.view}
    out = {}
    for name, a in args.items():
        touch(a, 1)
        best = np.inf
        for _ in range(3):
            t = time.perf_counter()
            for _ in range(reps):
                touch(a, 1)
            best = min(best, (time.perf_counter() - t) / reps)
        fields = len(a) if isinstance(a, tuple) else 1
        out[name] = {"us_per_call": 1e6 * best, "arrays": fields}
    return out
