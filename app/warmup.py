"""Compile the physics kernels for the open scene first, on both cores, while the window works.

numba compiles on first call; a cold first launch compiles about 130 kernels.  The window draws
the scene and its panels from its first frame without any kernel (``app.preview``): the user can
select, inspect, pan, zoom and open scenes; only stepping waits.  The open scene's step is split
in two (``app.compile_units.gate_units``), each half compiled in a helper process
(``app.compile_helper``), one per core: the solver mode in one, the collision stages and the
frame's kernels in the other.  Not in this process: numba compiles holding the interpreter lock
for most of its time, and every OpenGL call of a frame gives the lock up and waits up to the
switch interval (5 ms) to get it back, so with a compile thread here the window had to throttle
itself to 4 frames a second (and showed no panels until the end).  When both halves are
in numba's disk cache, one probe step here loads them (seconds, the only wait under the lock) and
the scene may run (``ready``).  After that the first helper goes on with the other broad phases
and solver modes; switching to one loads it from the cache (``prioritize``), or compiles it next
if the helper has not got there yet.  Without helpers (``helper=False``, the unit tests) this
process compiles its half in its own thread, as before.

Each unit that is in the cache leaves a marker file in numba's cache directory (which is keyed
on the physics sources, so an edit of ``physics/`` starts again): a launch whose units are all
marked loads everything here, without starting the helper.

soft_step's whole step as one compiled call (``physics.step.one_call``) is not in the gate: the
scene plays through the pipeline's stages (the same kernels the gate compiled, the same bits)
while the first helper compiles the driver (``final``), and steps through it from the step after
it is loaded here.  A mode switched to waits for its solver and broad phase only, likewise.

Progress is counted in kernels really compiled (every process), per unit, against what the last
cold launch compiled for the units still to do (``app.compile_progress``).  The window throttles
its frame rate while this process compiles or loads (see ``busy``).
"""
from __future__ import annotations

import contextlib
import os
import threading
import time
import traceback
from . import compile_units
from . import compile_progress
from .compile_helper import CompileHelper
from .compile_worker import listen

FIRST_FRAME_WAIT = 10.0   # s: compile here after the first frame, or after this without a window


class _Counter:
    """Kernels compiled in this process (numba's compile events) and the one compiling now."""

    def __init__(self):
        self.n = 0
        self.label = ""
        listen(self._start, self._end)

    def _start(self, name):
        self.label = name

    def _end(self, name):
        self.n += 1


_COUNTER = None


class Warmup:
    """``Warmup(world, lock)``; ``start()`` begins.  ``lock`` is the physics lock the simulation
    steps under (a kernel first called here compiles or loads under it)."""

    def __init__(self, world, lock: threading.Lock, helper: bool = True):
        global _COUNTER
        if _COUNTER is None:
            _COUNTER = _Counter()
        self.counter = _COUNTER
        self.lock = lock
        self.solver, self.integrator = world.solver, world.integrator
        self.broadphase = compile_units.broadphase_of(world)
        self.key = (self.solver, self.integrator, self.broadphase)
        self.narrow = compile_units.narrow_unit(world)
        self.cache = compile_units.cache_dir()
        # nothing compiled into this cache yet: the progress may say "first launch only"
        self.first_launch = self.cache is None or not any(self.cache.glob("unit-*.ok"))
        mine, theirs = compile_units.gate_units(*self.key, self.narrow)
        self.gate = mine + theirs     # loaded here once the scene can run (the last step loads them)
        # the one-call step's driver for this world: after the gate (the module docstring; the
        # sandbox's main turns physics' compile_on_demand off, so the scene plays meanwhile)
        self.final = "step:" + ":".join(self.key) + (":full" if self.narrow != "narrow" else "") + \
            (":joints" if world.joints else "")
        # the mode's joint stage is the largest unit (182 CPU s cold, measured alone: it compiles
        # the step again with the joint table).  A scene with joints waits for it; any other scene
        # plays without it, while the helper compiles it first of the background units (the first
        # mouse drag, a joint, waits for it: app/simulation.py)
        joints = compile_units.joints_unit(self.solver, self.integrator)
        self.after_final = [joints] if world.joints else []
        background = [u for u in compile_units.background_units(*self.key, self.narrow)
                      if not self.cached(u)]
        if os.environ.get("STELKROPP_BACKGROUND_COMPILE", "1") == "0":
            background = []     # other modes only when switched to (e.g. a CI box with one core)
        if not self.cached(self.final):
            background.insert(0, self.final)    # the scene plays without it meanwhile
        if not world.joints and not self.cached(joints):
            background.insert(0, joints)    # the open mode's own: the drag needs it in any case
        self.joints = joints
        self.background = background
        self.warm = all(self.cached(u) for u in mine + theirs + self.after_final)
        if self.warm:
            mine, theirs = [], []      # all on disk: one probe step here loads it all, at once
        self.mine, self.theirs = mine, theirs
        self.helper = CompileHelper(self._changed) if helper and (theirs or background) else None
        # this process's half in a second helper process too (the module docstring says why)
        self.second = CompileHelper(self._changed) if helper and mine else None
        # when the helper is done with its share first, it takes the other half's last units
        # (the other process then finds them in the cache: compile_units.unit_lock)
        self._initial_queue = theirs + mine[:0:-1] + background
        self.todo = [u for u in mine + theirs + self.after_final if not self.cached(u)]
        self.counts = compile_progress.KernelCounts(self._counts_path())
        self.here: dict[str, int] = {}          # kernels compiled in this process, per unit
        self._n0 = self.counter.n               # the counter when the unit running here began
        self.warmed: set[tuple[str, str, str]] = set()
        self.loaded: set[str] = set()           # units loaded (or compiled) in this process
        self.failed: set[str] = set()           # units that raised here (the step then shows why)
        self._wanted_units: list[str] = []      # units the window waits for (a mode's joint stage)
        self.errors: list[str] = []
        self.label = "starting"
        self.stage = "starting"
        self.t0 = time.monotonic()
        self.t_gate = None
        self._ready = False
        self._cv = threading.Condition()
        self._wanted: list[tuple[str, str, str]] = []
        self._busy = False
        self._drawn = threading.Event()
        self.thread = threading.Thread(target=self._run, name="kernel-warmup", daemon=True)

    # -- the marker files and the expected counts -----------------------------------------
    @staticmethod
    def cached(unit: str) -> bool:
        return compile_units.cached(unit)

    def _counts_path(self):
        return None if self.cache is None else self.cache.parent / "kernel_counts.json"

    # -- running -----------------------------------------------------------------------
    def start(self):
        if self.helper is not None and not self.warm:
            self._start_helper()
        if self.second is not None:
            self.second.queue = list(self.mine)
            self.second.start()
        self.thread.start()
        return self

    def _start_helper(self):
        self.helper.queue = list(self._initial_queue)
        self.helper.start()

    def close(self) -> None:
        """Stop the helper processes (the sandbox is closing)."""
        for h in (self.helper, self.second):
            if h is not None:
                h.close()

    def _changed(self):
        with self._cv:
            self._cv.notify_all()

    def _unit(self, unit: str, locked: bool = True) -> None:
        """Compile or load ``unit`` here, under the physics lock unless not ``locked``: after the
        gate the scene runs, and a unit's probe world shares nothing with it (numba's own lock
        serialises compiles), so a rival mode loading here leaves the main world stepping."""
        self.stage = unit
        self._n0 = self.counter.n
        self._busy = True
        try:
            with compile_units.unit_lock(unit), (self.lock if locked else contextlib.nullcontext()):
                compile_units.run(unit)
        except Exception as exc:  # noqa: BLE001  (a broken mode must not stop the others)
            self.errors.append(f"{unit}: {exc}")
            self.failed.add(unit)
            traceback.print_exc()
        else:
            compile_units.mark(unit)
            self.loaded.add(unit)
        finally:
            self.here[unit] = self.here.get(unit, 0) + self.counter.n - self._n0
            self._busy = False

    def _wait_helper(self, units, locked: bool = True, helper=None) -> None:
        """Wait until ``helper`` (the first one unless given) settled ``units``; compile here the
        ones it could not."""
        helper = helper or self.helper
        units = [u for u in units if not compile_units.cached(u)]
        if helper is None:
            for u in units:
                self._unit(u, locked)
            return
        for u in units:
            helper.push(u, first=True)
        with self._cv:
            self._cv.wait_for(lambda: all(helper.settled(u) for u in units))
        for u in units:
            if u not in helper.done:
                self._unit(u, locked)     # the helper failed or died: compile it here

    def frame_drawn(self) -> None:
        """The window has drawn its first frame: this process may start compiling (the helper
        started at once; a compile here would hold the interpreter lock the first frame needs)."""
        self._drawn.set()

    def _run(self):
        if self.second is not None:
            self._compile_apart()
        else:
            self._compile_here()
        for u in self.after_final:
            self._unit(u)
        if self.cached(self.final):
            self._unit(self.final)     # on disk: loaded now (else the helper's first background unit)
        self.counts.save({u: self._compiled(u) for u in self.todo})
        self.warmed.add(self.key)
        self.loaded.update(self.gate)
        self.t_gate = time.monotonic() - self.t0
        self._ready = True
        if self.helper is not None and self.warm:
            self._start_helper()       # the background units, now that the scene runs
        if self.cached(self.joints):
            self.want_unit(self.joints)    # on disk: loaded now, so the first drag does not wait
        self._serve()

    def _compile_apart(self):
        """The gate in the helper processes: the halves at once, then the whole step and (a
        scene with joints) the joint stage in the second, so that this process only loads."""
        self.stage = "waiting for the compiler processes"
        self._wait_helper(self.mine, helper=self.second)
        self._wait_helper(self.theirs)
        self._wait_helper(self.after_final, helper=self.second)
        self.second.close()        # the first helper goes on with the background units

    def _compile_here(self):
        """The gate without a second helper: this process's half in this thread."""
        if not self.warm:      # a cold compile would hold up the first frame; loading would not
            self._drawn.wait(FIRST_FRAME_WAIT)
        pending = []
        for u in self.mine:
            if self.helper is None or self.helper.claim(u):
                self._unit(u)
            else:
                pending.append(u)      # the helper got there first
        self.stage = "waiting for the other core"
        self._wait_helper(self.theirs + pending)

    def _serve(self):
        """After the gate: load the modes the user switches to (``prioritize``) and their joint
        stages (``want_unit``), and the open mode's joint stage and the quadtree overlay's kernels
        once the helper has them (the joint stage is the mouse drag's: a scene without joints
        plays before the helper has it, and the first drag should not wait for it then)."""
        later = [u for u in (self.joints, self.final, "extras")
                 if self.helper is not None and u in self._initial_queue and u not in self.loaded]

        def settled():
            return [u for u in later if self.helper.settled(u)]
        while True:
            with self._cv:
                self._cv.wait_for(lambda: self._wanted or self._wanted_units or settled())
                unit = self._wanted_units.pop(0) if self._wanted_units else None
                key = self._wanted.pop(0) if self._wanted and unit is None else None
            if unit is not None:      # the window waits for it: here now, unless the helper is on it
                self.label = unit
                if self.helper is not None and not self.helper.claim(unit):
                    self._wait_helper([unit], locked=False)
                self._unit(unit, locked=False)
                if unit in later:
                    later.remove(unit)
                continue
            if key is None:
                unit = settled()[0]
                later.remove(unit)
                self._unit(unit, locked=False)
                continue
            solver, integrator, bp = key
            self.label = f"{solver} ({integrator})"
            self._wait_helper([f"solve:{solver}:{integrator}", f"broad:{bp}"], locked=False)
            self.warmed.add(key)     # the pipeline's stages step it; the driver follows
            step = "step:" + ":".join(key)
            h = self.helper
            if h is not None and h.alive and not self.cached(step):
                if step not in later and step not in self.loaded:
                    h.push(step, first=True)       # compiled there, loaded here once settled
                    later.append(step)
            else:
                self._unit(step, locked=False)     # on disk (a load), or no helper process
            # what this mode compiled: the next switch to it on a cold cache counts against it
            self.counts.save({u: self._compiled(u) for u in self.mode_units(*key)})

    # -- what the window asks --------------------------------------------------------
    def _mode_key(self, solver: str, integrator: str,
                  broadphase: str | None = None) -> tuple[str, str, str]:
        """(solver, integrator, broad phase) as the compile units name a mode: the integrator as
        the mode steps with it (a mode that integrates its own way ignores the setting), the open
        scene's broad phase unless given."""
        return (solver, compile_units.step_integrator(solver, integrator),
                broadphase or self.broadphase)

    def prioritize(self, solver: str, integrator: str, broadphase: str | None = None,
                   first: bool = False) -> None:
        """Make this mode ready next (the user just switched to it); ``first``: before the other
        modes asked for (a comparison's rivals), since the user waits for this one."""
        key = self._mode_key(solver, integrator, broadphase)
        with self._cv:
            if key in self.warmed or (key in self._wanted and not first):
                return
            if key in self._wanted:
                self._wanted.remove(key)
            self._wanted.insert(0, key) if first else self._wanted.append(key)
            self._cv.notify_all()

    def want_apart(self, unit: str) -> None:
        """Load ``unit`` here once the helper process has compiled it (first in its queue), so
        that this process only loads it and the window keeps its frame rate meanwhile; without
        a helper (or once it has it in the cache), as ``want_unit``."""
        h = self.helper
        if unit in self.loaded or unit in self.failed:
            return
        if h is not None and h.alive and not compile_units.cached(unit) and not h.settled(unit):
            if unit != h.current and unit not in h.queue:
                h.push(unit, first=True)
            return
        self.want_unit(unit)

    def mode_units(self, solver: str, integrator: str, broadphase: str | None = None,
                   joints: bool = False) -> list[str]:
        """The units a switch to this mode loads (``_serve``) before it steps: its solver, the broad
        phase and, for a world with joints, its joint stage (its one-call step, where it has one,
        follows while it plays)."""
        key = self._mode_key(solver, integrator, broadphase)
        solver, integrator, bp = key
        units = [f"solve:{solver}:{integrator}", f"broad:{bp}"]
        return units + ([compile_units.joints_unit(solver, integrator)] if joints else [])

    def mode_progress(self, units: list[str]):
        """(fraction 0..1, the work left in words) for a mode switched to that is not loaded yet:
        ``units`` are its units that were not in the cache when the user picked it (counted as
        ``progress`` counts the open scene's)."""
        compiling = self._compiling()
        frac, done, left, waiting = compile_progress.progress(units, self._compiled, self._finished,
                                                              compiling, self.counts)
        text = compile_progress.describe(done, left, waiting, loading=self._busy)
        other = [u for u in compiling if u not in units]
        if waiting and other and not any(u in compiling for u in units):
            # the helper finishes what it started before the user asked (a unit is never cut short)
            text += f" (after {compile_progress.unit_name(other[0])}, compiling now)"
        return min(frac, 0.99), text

    def _compiling(self) -> dict[str, str]:
        """{unit: the kernel compiling now} in the helpers and here."""
        compiling = {}
        for h in self._helpers():
            unit = h.current          # read once: the reader thread clears it
            if unit is not None:
                compiling[unit] = h.label.rsplit(".", 1)[-1]
        if self._busy:
            compiling[self.stage] = self.counter.label.rsplit(".", 1)[-1]
        return compiling

    def want_unit(self, unit: str) -> None:
        """Load ``unit`` next: here (from the cache, or compiled), or after the helper if it is
        compiling it now."""
        with self._cv:
            if unit in self.loaded or unit in self.failed or unit in self._wanted_units:
                return
            self._wanted_units.append(unit)
            self._cv.notify_all()

    def joints_ready(self, solver: str, integrator: str) -> bool:
        """Is this mode's joint stage loaded here (a step with joints will not stop to compile)?
        A stage that failed to compile counts as ready: the step then reports the failure."""
        unit = compile_units.joints_unit(solver, integrator)
        return unit in self.loaded or unit in self.failed

    def narrow_ready(self, unit: str) -> bool:
        """Is this narrow-phase unit (``compile_units.narrow_unit``: the lean kernel or the whole
        one) loaded here?  A failed one counts as ready, as for joints (the step says why)."""
        return self._ready and (unit in self.loaded or unit in self.failed)

    def can_step(self, solver: str, integrator: str, broadphase: str | None = None) -> bool:
        """Are the kernels of this mode loaded here (a step will not stop to compile)?"""
        return self._ready and self._mode_key(solver, integrator, broadphase) in self.warmed

    @property
    def ready(self) -> bool:
        """The open scene can run (its kernels are loaded)."""
        return self._ready

    @property
    def busy(self) -> bool:
        """Is this process compiling or loading (the window leaves it the interpreter)?"""
        return self._busy

    @property
    def finished(self) -> bool:
        return self._ready and not self._busy and not (self.helper is not None and self.helper.busy())

    def _helpers(self):
        return [h for h in (self.helper, self.second) if h is not None]

    def _compiled(self, unit: str) -> int:
        """Kernels compiled for ``unit`` so far, in every process (the one compiling now too)."""
        n = self.here.get(unit, 0) + sum(h.unit_kernels.get(unit, 0) for h in self._helpers())
        if self._busy and self.stage == unit:
            n += self.counter.n - self._n0
        return n

    def _finished(self, unit: str) -> bool:
        return unit in self.loaded or unit in self.failed or \
            any(unit in h.done or unit in h.failed for h in self._helpers())

    def kernels_compiled(self) -> int:
        """Kernels compiled so far for this launch's gate, in every process."""
        return sum(self._compiled(u) for u in self.todo)

    def progress(self, extra=()):
        """(fraction 0..1 of the open scene's kernels compiled, the work left and what the scene
        waits for, in words: ``app.compile_progress``).  ``extra``: units the open scene needs
        beyond the gate (``app.scene_wait``), counted after it."""
        if self._ready:
            return self.mode_progress(list(extra)) if extra else (1.0, "ready")
        compiling = self._compiling()
        units = self.todo + [u for u in extra if u not in self.todo]
        frac, done, left, waiting = compile_progress.progress(units, self._compiled, self._finished,
                                                              compiling, self.counts)
        return min(frac, 0.99), compile_progress.describe(done, left, waiting, loading=self._busy)

    def elapsed(self) -> float:
        return time.monotonic() - self.t0
