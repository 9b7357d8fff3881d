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

from physics import options
from physics.compile_units import (_marker, cache_dir, cached, mark, needs_full_narrowphase,  # noqa: F401
                                   probe_world, run_unit, step_integrator)  # (the app's names)


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
    run_unit(unit)


NARROW_UNITS = ("narrow", "narrow:full")


def narrow_unit(world) -> str:
    """The narrow-phase unit ``world`` steps with: "narrow", the lean kernel (SAT, sharp polygons
    and circles), unless its narrow phase is GJK, it has a rounded shape (a capsule, segment or
    rounded polygon) or a chain, or it has met such a pair before: then "narrow:full".  (Shape
    for shape this says "full" for a few worlds the lean kernel would serve, such as capsules
    that only meet circles: the wait is then for nothing, never a compile in the window.)"""
    return "narrow:full" if needs_full_narrowphase(world) else "narrow"


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
