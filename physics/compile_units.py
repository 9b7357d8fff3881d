"""Compile the core's kernels ahead of the first step: ``physics.precompile(...)``.

numba compiles a kernel on its first call and keeps the machine code in its disk cache
(physics/_jit.py).  A step runs independent groups of kernels, called *units* here: one broad
phase, the narrow phase (the lean kernel, or the full one with GJK, EPA, rounded shapes and
chains), the solver mode's step, its joint stage, the kernels that open and close a step, and
the rest of a frame (geometry, islands, contacts, picking, queries).  Each unit calls its group's
entry points on a small throwaway world: only the argument types matter to the compiler, so the
results are thrown away.  Units share no state, so several processes can fill one cache at once,
each with its own units; a later process loads them all from disk.

Unit names: ``broad:<broadphase>``, ``narrow`` (lean), ``narrow:full``, ``solve:<mode>:<integrator>``,
``joints:<mode>:<integrator>``, ``guard``, ``frame``, ``extras`` (quadtree cells, shape casts)
and ``step:<mode>:<integrator>:<broadphase>[:full][:joints]``.
``solve``, ``joints`` and ``step`` compile both a world with springs and one without (soft_step
compiles its spring solve only for the first: store/optional.py), so adding a spring never waits
(a whole step: whatever the others left, such as the one-call step's variant for a world with
the whole narrow phase or with joints: physics/step/soft_driver.py).  The sandbox, CI (``python -m physics precompile``)
and the tuner all go through here.
"""
from __future__ import annotations

import os
import sys
import time

from . import options


def probe_world(solver: str = options.DEFAULT_SOLVER, integrator: str = options.DEFAULT_INTEGRATOR,
                broadphase: str = "brute", springs: bool = True):
    """A small world with every body kind, both sharp shape kinds, polygons of two vertex counts
    and (``springs``) a spring to the world, so each stage meets every argument type a scene can
    give it."""
    from . import Circle, Polygon, World
    w = World(solver=solver, integrator=integrator, broadphase=broadphase)
    w.add_body(Polygon.box(10, 1), kind="static", position=(0, -0.5))
    w.add_body(Polygon.box(1, 1), position=(0, 0.49))
    w.add_body(Polygon.box(1, 1), position=(0.2, 1.5), angle=0.1)
    w.add_body(Circle(0.4), position=(1.5, 0.45))
    w.add_body(Circle(0.4), position=(1.6, 1.3))
    hexa = w.add_body(Polygon.regular(6, 0.5), position=(-1.5, 0.45))
    w.add_body(Polygon.box(0.5, 0.5), kind="kinematic", position=(-3, 1), velocity=(0.1, 0))
    if springs:
        w.add_spring(hexa, None, anchor_b=(-1.5, 2.0), stiffness=50.0, damping=0.5)
    return w


def _broad(bp):
    from .collision import broadphase
    from .collision.broadphase.fixture_filter import filter_pairs_flat
    w = probe_world(broadphase=bp)
    w._pipeline.refresh_geometry(w, w.dt)
    s = w._store
    flat = s.fixtures.arrays.flat
    n, pairs = broadphase.find_pairs(s.fixtures.view, s.fixtures.n, bp, w._pipeline._pairs, flat=flat)
    filter_pairs_flat(*flat, pairs, n, w._pipeline._no_keys)


def _narrow(kind: str = "lean"):
    """The narrow phase's lean kernel (SAT; sharp polygons and circles), or with ``kind`` "full"
    the whole one (GJK, EPA, rounded shapes, chains): physics/collision/narrowphase/kernel.py."""
    from .collision import narrowphase
    w = probe_world()
    w._store.contacts.full = kind == "full"
    p, s = w._pipeline, w._store
    p._refresh(w, w.dt)
    p.refresh_geometry(w, w.dt)
    # no pairs: numba compiles for the argument types, so the broad phase is not needed here
    narrowphase.collide(p.ctx, s.bodies.arrays, s.fixtures.arrays, s.verts.arrays, p._pairs, 0, s.contacts)


def _solve(solver, integrator):
    for springs in (False, True):
        w = probe_world(solver, integrator, springs=springs)
        p = w._pipeline
        p._refresh(w, w.dt)
        p.solve(w, w.dt)


def _guard():
    """The two kernels that open and close every step (physics/step/frame.py: checkpoint, energy
    guard, finite check, touch events), the same for every mode."""
    w = probe_world()
    p = w._pipeline
    p._refresh(w, w.dt)
    p.open_step(w)
    p._guard.begin(w)
    p.close_step(w)
    # the probe's moving kinematic body is external input, which turns the guard off for the
    # step; its bound is compiled all the same (a scene at rest plays with it on)
    from .step.energy_bound import ACTIVE
    p._guard.G[ACTIVE] = 1.0
    p._guard.excess(w, w.dt)


def _frame():
    w = probe_world()
    p = w._pipeline
    p._refresh(w, w.dt)
    w.render_data()
    p.sleep(w, w.dt)
    w.contacts()
    w.query_point((0.0, 0.5))
    w.ray_cast((-5.0, 0.5), (5.0, 0.5), first=True)     # the sandbox's laser beams
    w.ray_cast((-5.0, 0.5), (5.0, 0.5))


def _extras():
    """The quadtree overlay and the shape queries (physics/queries)."""
    from . import Circle
    w = probe_world()
    w.quadtree_cells()
    w.step()
    w.query_aabb((-1.0, -1.0), (1.0, 1.0))
    w.overlap(Circle(0.2), (0.0, 0.5))
    w.shape_cast(Circle(0.2), (0.0, 5.0), 0.0, (0.0, -5.0))


def _step(solver, integrator, bp, *flags):
    """Three whole steps of the probe world (``full``: with the whole narrow phase; ``joints``:
    with a joint; ``threads``: with enough boxes for the driver with split loops, where this
    machine runs more than one thread: physics/threads.py), so the one-call step's variant for
    such a world is compiled too; with a
    spring and without.  The driver is compiled here even where worlds wait for it (the
    sandbox: physics/step/one_call.py, ``compile_on_demand``)."""
    from .step.one_call import compile_on_demand
    was = compile_on_demand(True)
    try:
        _probe_steps(solver, integrator, bp, flags)
    finally:
        compile_on_demand(was)


def _probe_steps(solver, integrator, bp, flags):
    for springs in (False, True):
        w = probe_world(solver, integrator, bp, springs=springs)
        w._store.contacts.full = "full" in flags
        if "joints" in flags:
            w.add_joint("revolute", w.bodies[2], w.bodies[1], anchor=(0.1, 1.0))
        if "threads" in flags:
            _crowd(w)
        for _ in range(3):
            w.step()
    w.render_data()
    w.contacts()
    w.query_point((0.0, 0.5))


def _crowd(w):
    """threads.SPLIT_SIZE boxes resting in rows on a floor beside the probe world's bodies."""
    from . import Polygon, threads
    w.add_body(Polygon.box(200, 1), kind="static", position=(150, -0.5))
    per_row = 100
    for k in range(threads.SPLIT_SIZE):
        w.add_body(Polygon.box(1, 1), position=(52 + 1.01 * (k % per_row), 0.5 + 1.0 * (k // per_row)))


def _joints(solver, integrator):
    """Steps of the probe world with one joint of every kind the sandbox's tools make (and the
    mouse drag's), so the joint stage of this mode is in the cache; with a spring and without.
    The pipeline's stages only: the one-call step's variant with joints is ``step:...:joints``'s."""
    for springs in (False, True):
        w = probe_world(solver, integrator, springs=springs)
        ground, box, top, disc = w.bodies[0], w.bodies[1], w.bodies[2], w.bodies[3]
        w.add_joint("revolute", top, box, anchor=(0.1, 1.0), motor_speed=1.0, max_motor_torque=5.0)
        w.add_joint("weld", box, ground, anchor=(0.0, 0.0))
        w.add_joint("prismatic", top, None, anchor=(0.2, 1.5), axis=(0.0, 1.0), lower=-1.0, upper=1.0)
        w.add_joint("distance", disc, None, anchor_b=(1.5, 3.0), max_length=3.0)
        w.add_joint("wheel", box, w.bodies[4], anchor=(1.6, 1.3))
        w.add_joint("motor", w.bodies[5], ground)
        w.add_joint("mouse", w.bodies[4], None, target=(2.0, 2.0))
        w._pipeline.one_call.enabled = False
        for _ in range(3):
            w.step()


_UNITS = {"broad": _broad, "narrow": _narrow, "guard": _guard, "solve": _solve, "frame": _frame,
          "extras": _extras, "step": _step, "joints": _joints}


def run_unit(unit: str) -> None:
    """Compile (or load from the cache) the kernels of ``unit``; ValueError for an unknown name."""
    kind, *args = unit.split(":")
    fn = _UNITS.get(kind)
    if fn is None:
        raise ValueError(f"unknown compile unit {unit!r}")
    fn(*args)


def step_integrator(solver: str, integrator: str) -> str:
    """The integrator a step of ``solver`` compiles for: ``integrator`` where the mode uses the
    world's setting, else the default (soft_step and sequential_impulse integrate their own way,
    so their kernels are the same whatever the setting)."""
    from . import solvers
    return integrator if solvers.get(solver).uses_integrator else options.DEFAULT_INTEGRATOR


def _integrators(solver: str) -> tuple:
    from . import solvers
    return options.INTEGRATORS if solvers.get(solver).uses_integrator else (options.DEFAULT_INTEGRATOR,)


def units(world=None, modes=None) -> list[str]:
    """The units a world (or, with ``world`` None, every mode in ``modes``: default all) needs,
    the ones every step runs first, then the costliest first so two processes end together."""
    if world is not None:
        from .collision.broadphase import resolve
        bp = resolve(world.broadphase, world._store.fixtures.n)
        narrow = "narrow:full" if needs_full_narrowphase(world) else "narrow"
        out = [f"solve:{world.solver}:{world.integrator}", narrow, f"broad:{bp}", "guard", "frame"]
        if world._store.joints.n:
            out.append(f"joints:{world.solver}:{world.integrator}")
        from .step.one_call import splits
        out.append(f"step:{world.solver}:{world.integrator}:{bp}" + (":full" if narrow != "narrow" else "")
                   + (":joints" if world._store.joints.n else "") + (":threads" if splits(world) else ""))
        return out
    modes = options.SOLVERS if modes is None else tuple(modes)
    out = []
    for m in modes:
        out += [f"solve:{m}:{i}" for i in _integrators(m)]
    out += ["narrow", "narrow:full", "guard", "frame", "broad:brute", "broad:sweep", "broad:quadtree"]
    for m in modes:
        out += [f"joints:{m}:{i}" for i in _integrators(m)]
    out.append("extras")
    out += [f"step:{m}:{options.DEFAULT_INTEGRATOR if options.DEFAULT_INTEGRATOR in _integrators(m) else _integrators(m)[0]}:sweep:full"
            for m in modes]
    if options.DEFAULT_SOLVER in modes:  # the one-call step's variants the units above leave out
        out += [f"step:{options.DEFAULT_SOLVER}:{options.DEFAULT_INTEGRATOR}:brute" + v
                for v in ("", ":full", ":joints", ":full:joints")]
        out.append(f"step:{options.DEFAULT_SOLVER}:{options.DEFAULT_INTEGRATOR}:sweep:threads")  # a large world
    return out


def needs_full_narrowphase(world) -> bool:
    """Does ``world`` step with the full narrow-phase kernel (GJK chosen, a rounded shape, a
    capsule, segment or chain, or such a pair met before) rather than the lean SAT one?"""
    import numpy as np

    from .store.fixtures import CAPSULE, POLYGON
    s = world._store
    if world.narrowphase != "sat" or s.contacts.full:
        return True
    n = s.fixtures.n
    shape = s.fixtures.view.shape[:n]
    rounded = (shape == POLYGON) & (s.fixtures.view.radius[:n] > 0.0)
    return bool(np.any(shape >= CAPSULE) or np.any(rounded))


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


def _worker(unit: str):
    from .compile_checks import literals_checked, returns_checked
    t0, c0 = time.time(), time.process_time()
    with returns_checked(), literals_checked():
        run_unit(unit)
    mark(unit)
    return unit, time.time() - t0, time.process_time() - c0


def _chain(units_: list) -> list:
    """Run ``units_`` one after the other in this process (a pool task)."""
    return [_worker(u) for u in units_]


#: units that share kernels compile in one process, one after the other: two processes compiling
#: the same kernel at once both pay for it (the joint stages of soft_step and sequential_impulse
#: share their rows; the seed modes share their integrators and contact model)
_FAMILIES = (("soft_step", "sequential_impulse"), ("impulse",), ("penalty", "hybrid"))


def chains(todo: list) -> list[list]:
    """``todo`` split into chains of units that share kernels, the costliest first, so a pool of
    workers takes them longest-first (LPT scheduling); the whole steps last, as one chain."""
    def family(u):
        kind, *args = u.split(":")
        if kind in ("solve", "joints", "step") and args:
            return next((k for k, f in enumerate(_FAMILIES) if args[0] in f), len(_FAMILIES))
        return len(_FAMILIES)           # collision, frame and the rest
    groups: dict = {}
    for u in todo:
        groups.setdefault(family(u), []).append(u)
    steps = [u for u in todo if u.startswith("step:")]
    # costliest first (measured cold: collision ~130 CPU s, soft_step with sequential_impulse ~120,
    # impulse ~65, penalty with hybrid ~45): the collision stages, then the families in order
    order = [len(_FAMILIES)] + list(range(len(_FAMILIES)))
    out = [[u for u in groups.get(k, []) if not u.startswith("step:")] for k in order]
    return [c for c in out if c] + ([steps] if steps else [])   # whole steps last: they only load what the rest compiled


def precompile(what=None, jobs: int = 1, progress=None) -> list[tuple[str, float, float]]:
    """Compile what ``what`` needs into numba's disk cache, on ``jobs`` processes.

    ``what``: a :class:`~physics.World` (the units its next step and its joints need), a mode
    name or a list of them (every unit of those modes), or None for every mode.  ``progress``:
    called with one line per finished unit or chain (default: print to stderr).  Returns
    ``[(unit, wall seconds, CPU seconds), ...]`` in the order they finished.  With ``jobs`` > 1
    the units run in worker processes that share the cache directory, kernels that units share
    in one process (:func:`chains`); a failure raises here after the others finished.
    """
    from . import World
    if isinstance(what, World):
        todo = units(world=what)
    elif what is None or what == "all":
        todo = units()
    else:
        todo = units(modes=[what] if isinstance(what, str) else list(what))
    say = progress if progress is not None else (lambda line: print(line, file=sys.stderr, flush=True))
    done = []
    if jobs <= 1:
        for k, u in enumerate(todo, 1):
            done.append(_worker(u))
            say(f"[{k}/{len(todo)}] {u}: {done[-1][1]:.1f} s")
        return done
    import concurrent.futures as cf
    import multiprocessing as mp
    work = chains(todo)
    with cf.ProcessPoolExecutor(max_workers=jobs, mp_context=mp.get_context("spawn")) as pool:
        last = work.pop() if work and work[-1][0].startswith("step:") else None
        futures = [pool.submit(_chain, c) for c in work]
        errors = []
        for fut in cf.as_completed(futures):
            try:
                for row in fut.result():
                    done.append(row)
                    say(f"[{len(done)}/{len(todo)}] {row[0]}: {row[1]:.1f} s")
            except Exception as exc:  # noqa: BLE001  (report every failure, then raise the first)
                errors.append(exc)
                say(f"failed: {type(exc).__name__}: {exc}")
        if last and not errors:
            for row in pool.submit(_chain, last).result():
                done.append(row)
                say(f"[{len(done)}/{len(todo)}] {row[0]}: {row[1]:.1f} s")
    if errors:
        raise errors[0]
    return done


def default_jobs() -> int:
    """Worker processes for a precompile: the machine's cores (at least one)."""
    return max(1, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1))
