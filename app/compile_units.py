"""The compile units of the sandbox's first launch: which kernels each one compiles, on a probe world.

numba compiles a kernel (and every kernel it calls) on its first call and keeps it in its disk
cache.  A step runs three independent groups of kernels (docs/internals.md): the collision stages
(one broad phase and the narrow phase), the solver mode's step, and the rest of the frame (geometry,
islands, contacts, picking, drawing).  Each unit here calls one group's entry points on a small
throwaway world, so two processes can fill the cache at once, each with its own group, and the
sandbox loads the other's from disk.  Calling a stage out of order on a probe world is fine: only
the argument types matter to the compiler, the results are thrown away.

Unit names: ``broad:<broadphase>``, ``narrow`` (the lean kernel), ``narrow:full``,
``solve:<solver>:<integrator>``, ``frame``,
``guard`` (the kernels that open and close a step), ``extras`` (the quadtree overlay),
``step:<solver>:<integrator>:<broadphase>[:full]`` (a whole step: what is left),
``joints:<solver>:<integrator>`` (the joint stage, which a step compiles only once a world has a
joint: loaded before a scene with joints runs, else compiled by the helper right after the gate,
since the mouse drag is a joint; and for a mode switched to before a world with joints steps in it,
so no step stops the window to compile).
"""
from __future__ import annotations

import os
import time

import numpy as np

import physics
from physics import options
from physics.store.fixtures import CAPSULE, POLYGON
from physics.collision import broadphase, narrowphase
from physics.collision.broadphase.fixture_filter import filter_pairs


def probe_world(solver: str, integrator: str = options.DEFAULT_INTEGRATOR, broadphase: str = "brute"):
    """A small world with every body kind, both shape kinds, polygons of two vertex counts and a
    spring to the world, so each stage meets every argument type a scene can give it."""
    w = physics.World(solver=solver, integrator=integrator, broadphase=broadphase)
    w.add_body(physics.Polygon.box(10, 1), kind="static", position=(0, -0.5))
    w.add_body(physics.Polygon.box(1, 1), position=(0, 0.49))
    w.add_body(physics.Polygon.box(1, 1), position=(0.2, 1.5), angle=0.1)
    w.add_body(physics.Circle(0.4), position=(1.5, 0.45))
    w.add_body(physics.Circle(0.4), position=(1.6, 1.3))
    hexa = w.add_body(physics.Polygon.regular(6, 0.5), position=(-1.5, 0.45))
    w.add_body(physics.Polygon.box(0.5, 0.5), kind="kinematic", position=(-3, 1), velocity=(0.1, 0))
    w.add_spring(hexa, None, anchor_b=(-1.5, 2.0), stiffness=50.0, damping=0.5)
    return w


def _broad(bp):
    w = probe_world(options.DEFAULT_SOLVER, broadphase=bp)
    w._pipeline.refresh_geometry(w, w.dt)
    s = w._store
    n, pairs = broadphase.find_pairs(s.fixtures.view, s.fixtures.n, bp, w._pipeline._pairs)
    filter_pairs(s.fixtures.view, pairs, n, w._pipeline._no_keys)


def _narrow(kind: str = "lean"):
    """The narrow phase's lean kernel (SAT; sharp polygons and circles), or with ``kind`` "full"
    the whole one (GJK, EPA, rounded shapes, chains): physics/collision/narrowphase/kernel.py."""
    w = probe_world(options.DEFAULT_SOLVER)
    w._store.contacts.full = kind == "full"
    p, s = w._pipeline, w._store
    p._refresh(w, w.dt)
    p.refresh_geometry(w, w.dt)
    # no pairs: numba compiles for the argument types, so the broad phase is not needed here
    narrowphase.collide(p.ctx, s.bodies.view, s.fixtures.view, s.verts.view, p._pairs, 0, s.contacts)


def _solve(solver, integrator):
    w = probe_world(solver, integrator)
    p = w._pipeline
    p._refresh(w, w.dt)
    p.solve(w, w.dt)


def _guard():
    """The two kernels that open and close every step (physics/step/frame.py: checkpoint, energy
    guard, finite check, touch events), the same for every mode."""
    w = probe_world(options.DEFAULT_SOLVER)
    p = w._pipeline
    p._refresh(w, w.dt)
    p.open_step(w)
    p.close_step(w)


def _frame():
    w = probe_world(options.DEFAULT_SOLVER)
    p = w._pipeline
    p._refresh(w, w.dt)
    w.render_data()
    p.sleep(w, w.dt)
    w.contacts()
    w.query_point((0.0, 0.5))
    w.ray_cast((-5.0, 0.5), (5.0, 0.5), first=True)     # the laser tool's beams
    w.ray_cast((-5.0, 0.5), (5.0, 0.5))


def _extras():
    probe_world(options.DEFAULT_SOLVER).quadtree_cells()


def _step(solver, integrator, bp, kind="lean"):
    w = probe_world(solver, integrator, bp)
    w._store.contacts.full = kind == "full"
    for _ in range(3):
        w.step()
    w.render_data()
    w.contacts()
    w.query_point((0.0, 0.5))


def _joints(solver, integrator):
    """A step of the probe world with one joint of every kind the sandbox's tools make (and the
    mouse drag's), so the joint stage of this mode is in the cache."""
    w = probe_world(solver, integrator)
    ground, box, top, disc = w.bodies[0], w.bodies[1], w.bodies[2], w.bodies[3]
    w.add_joint("revolute", top, box, anchor=(0.1, 1.0), motor_speed=1.0, max_motor_torque=5.0)
    w.add_joint("weld", box, ground, anchor=(0.0, 0.0))
    w.add_joint("prismatic", top, None, anchor=(0.2, 1.5), axis=(0.0, 1.0), lower=-1.0, upper=1.0)
    w.add_joint("distance", disc, None, anchor_b=(1.5, 3.0), max_length=3.0)
    w.add_joint("wheel", box, w.bodies[4], anchor=(1.6, 1.3))
    w.add_joint("motor", w.bodies[5], ground)
    w.add_joint("mouse", w.bodies[4], None, target=(2.0, 2.0))
    for _ in range(3):
        w.step()


def run(unit: str) -> None:
    """Compile (or load from the cache) the kernels of ``unit``; ValueError for an unknown name.

    With ``STELKROPP_UNIT_LOG=<file>`` each unit appends a line to that file (process id, unit,
    wall clock at start and end, CPU seconds of the process at start and end): the timeline of a
    launch in both processes (bench.launch reads it)."""
    log = os.environ.get("STELKROPP_UNIT_LOG")
    t0, c0 = time.time(), time.process_time()
    _run(unit)
    if log:
        with open(log, "a") as f:
            f.write(f"{os.getpid()} {unit} {t0:.3f} {time.time():.3f} {c0:.2f} {time.process_time():.2f}\n")


def _run(unit: str) -> None:
    kind, *args = unit.split(":")
    fn = {"broad": _broad, "narrow": _narrow, "guard": _guard, "solve": _solve, "frame": _frame,
          "extras": _extras, "step": _step, "joints": _joints}.get(kind)
    if fn is None:
        raise ValueError(f"unknown compile unit {unit!r}")
    fn(*args)


NARROW_UNITS = ("narrow", "narrow:full")


def narrow_unit(world) -> str:
    """The narrow-phase unit ``world`` steps with: "narrow", the lean kernel (SAT, sharp polygons
    and circles), unless its narrow phase is GJK, it has a rounded shape (a capsule, segment or
    rounded polygon) or a chain, or it has met such a pair before: then "narrow:full".  (Shape
    for shape this says "full" for a few worlds the lean kernel would serve, such as capsules
    that only meet circles: the wait is then for nothing, never a compile in the window.)"""
    s = world._store
    if world.narrowphase != "sat" or s.contacts.full:
        return "narrow:full"
    n = s.fixtures.n
    shape = s.fixtures.view.shape[:n]
    rounded = (shape == POLYGON) & (s.fixtures.view.radius[:n] > 0.0)
    return "narrow:full" if bool(np.any(shape >= CAPSULE) or np.any(rounded)) else "narrow"


def gate_units(solver: str, integrator: str, broadphase: str, narrow: str = "narrow"):
    """What the open scene needs before it can run, split in two: (this process's units, the
    helper's), about equal in CPU time.  Measured cold, each unit after the ones before it in
    one process (numba's compile events, bench/results/launch.md): the soft-step solver 26 CPU s,
    the sweep broad phase 3.5 and the step's own two kernels 4 here; the narrow phase 20 and the
    frame (geometry, islands, drawing, picking) 10.5 in the helper.  The last step here
    (``step:...``) then only loads; when the helper is done first it takes this process's last
    units."""
    return [f"solve:{solver}:{integrator}", f"broad:{broadphase}", "guard"], [narrow, "frame"]


def background_units(solver: str, integrator: str, broadphase: str, narrow: str = "narrow") -> list[str]:
    """Everything else the sandbox can switch to, the likeliest first: the other broad phases,
    the other narrow phase, the quadtree overlay, then the other solver modes.  (The open mode's
    joint stage is the gate's for a scene with joints, else the first background unit:
    app.warmup.)"""
    out = [f"broad:{bp}" for bp in ("brute", "sweep", "quadtree") if bp != broadphase]
    out += [u for u in NARROW_UNITS if u != narrow]
    out.append("extras")
    out += [f"solve:{s}:{integrator}" for s in options.SOLVERS if s != solver]
    return out


def joints_unit(solver: str, integrator: str) -> str:
    return f"joints:{solver}:{integrator}"


def cache_dir():
    """numba's cache directory for this version of ``physics/`` (None when caching is off)."""
    from pathlib import Path

    import numba.core.config as cfg
    return Path(cfg.CACHE_DIR) if cfg.CACHE_DIR else None


def _marker(unit: str):
    d = cache_dir()
    return None if d is None else d / f"unit-{unit.replace(':', '-')}.ok"


def cached(unit: str) -> bool:
    """Has ``unit`` been compiled into this cache (a marker file beside numba's)?"""
    m = _marker(unit)
    return m is not None and m.exists()


def mark(unit: str) -> None:
    """Note that ``unit``'s kernels are in the cache (the cache directory is keyed on the physics
    sources, so the marker goes with them)."""
    m = _marker(unit)
    if m is not None:
        try:
            m.write_text("")
        except OSError:
            pass


class unit_lock:
    """``with unit_lock(unit):`` one process at a time compiles ``unit`` into this cache (an
    advisory file lock: two sandboxes started together would otherwise both compile it; the
    second then loads it from the cache).  A no-op where file locks are unavailable."""

    def __init__(self, unit: str):
        m = _marker(unit)
        self.path = None if m is None else m.with_suffix(".lock")
        self._f = None

    def __enter__(self):
        try:
            import fcntl
            self._f = open(self.path, "w")
            fcntl.flock(self._f, fcntl.LOCK_EX)
        except (ImportError, OSError, TypeError):
            self._f = None
        return self

    def __exit__(self, *exc):
        if self._f is not None:
            self._f.close()      # closing releases the lock


def broadphase_of(world) -> str:
    """The broad phase ``world``'s next step runs ("auto" resolved by its fixture count)."""
    from physics.collision.broadphase import resolve
    return resolve(world.broadphase, world._store.fixtures.n)
