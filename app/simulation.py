"""Running the world: play/pause, the fixed-timestep accumulator, stepping under the physics lock
(the background compiler holds it while it warms kernels), faults, and the per-frame arrays the
velocity and quadtree overlays need."""
from __future__ import annotations

import threading
import time

import numpy as np

import physics

from . import compile_units

MAX_STEPS_PER_FRAME = 4


def waits_for(warmup, world, solver: str | None = None) -> str:
    """What a step of ``world`` in ``solver`` (default: its own mode) would wait for, in words
    ('': nothing, every kernel it runs is loaded here), asking the warmup for what is missing."""
    solver = solver or world.solver
    integrator = world.integrator
    bp = compile_units.broadphase_of(world)
    if not warmup.can_step(solver, integrator, bp):
        warmup.prioritize(solver, integrator, bp)
        return f"compiling {solver} ({integrator}, {bp} broad phase) ..."
    narrow = compile_units.narrow_unit(world)
    if not warmup.narrow_ready(narrow):
        # the narrow phase's lean and whole kernels compile apart: the other one loads (or
        # compiles) in the warmup thread, not in this step
        warmup.want_unit(narrow)
        return "compiling the narrow phase for these shapes ..."
    if world.joints and not warmup.joints_ready(solver, integrator):
        # the joint stage compiles once a world has a joint: in the warmup thread, not in this step
        warmup.want_unit(compile_units.joints_unit(solver, integrator))
        return f"compiling the joints of {solver} ({integrator}) ..."
    return ""


class Simulation:
    """Steps ``editor.world`` while ``running``; ``time_scale`` is simulated seconds per real second."""

    def __init__(self, editor, warmup, notices, paused=False, lock=None):
        self.editor = editor
        self.warmup = warmup
        self.notices = notices
        self.running = not paused
        self.time_scale = 1.0
        self.accumulator = 0.0
        self.fault = None
        self.speed = 1.0                       # measured simulated s per real s (running average)
        self.lock = lock if lock is not None else threading.Lock()   # shared with the warmup thread
        self.compiling_note = ""
        self.quadtree = np.zeros((0, 4))       # the last quadtree cells drawn (overlay Q)
        self.velocities = None                 # (N, 2) body velocities for the arrows (overlay V)
        self.after_step = None                 # called with the world after each step (the timeline)
        self._vel_key = None

    def reset(self):
        """A new document: no fault, nothing owed to the accumulator, no stale arrows."""
        self.fault = None
        self.accumulator = 0.0
        self.velocities = self._vel_key = None

    def toggle_run(self):
        self.running = not self.running
        if self.running:
            self.fault = None

    def step_once(self):
        self.running = False
        self.step(1)

    def step(self, n) -> float:
        """Take n steps if the kernels are ready and the lock is free; returns ms spent."""
        w = self.editor.world
        note = waits_for(self.warmup, w)
        if note:
            self.compiling_note = note
            return 0.0
        if not self.lock.acquire(blocking=False):
            self.compiling_note = "compiling kernels ..."
            return 0.0
        self.compiling_note = ""
        t0 = time.perf_counter()
        try:
            for _ in range(n):
                self.editor.tool.update(self.editor.cursor)
                w.step()
                if self.after_step is not None:
                    self.after_step(w)
        except physics.SimulationError as exc:
            self.fault = str(exc)
            self.running = False
            self.notices.notify(f"simulation error (world reverted, paused): {exc}", error=True)
        finally:
            self.lock.release()
        return (time.perf_counter() - t0) * 1e3

    def advance(self, real_dt, velocities=False):
        """Steps owed for ``real_dt`` real seconds (at most MAX_STEPS_PER_FRAME: slow motion rather
        than a spiral when we cannot keep up).  Returns (physics ms, steps taken); ``speed``
        follows the simulated time per real time actually achieved."""
        if not self.running:
            return 0.0, 0
        w = self.editor.world
        t_sim = w.time
        self.accumulator += min(real_dt, 0.25) * self.time_scale
        steps = int(self.accumulator / w.dt)
        if steps > MAX_STEPS_PER_FRAME:
            steps = MAX_STEPS_PER_FRAME
            self.accumulator = 0.0
        else:
            self.accumulator -= steps * w.dt
        phys_ms = self._steps_with_arrows(steps) if velocities else (self.step(steps) if steps else 0.0)
        if real_dt > 0:
            self.speed = 0.9 * self.speed + 0.1 * (w.time - t_sim) / min(real_dt, 0.25)
        return phys_ms, steps

    def _steps_with_arrows(self, steps) -> float:
        """Step, and keep each body's displacement over the steps / the time stepped for the
        velocity arrows, from the render arrays (no per-body Python handles)."""
        if not steps:
            return 0.0
        w = self.editor.world
        before = w.render_data()
        x0, ids0, t0 = before.center.copy(), before.ids.copy(), w.time
        phys_ms = self.step(steps)
        after = w.render_data()
        if w.time > t0 and np.array_equal(after.ids, ids0):
            self.velocities = (after.center - x0) / (w.time - t0)
            self._vel_key = ("stepped", self.editor.doc.history.version, w.steps, len(ids0))
        else:
            self.velocities = None
        return phys_ms

    def body_velocities(self, rd):
        """Velocities for the arrow overlay, in render-data order.  While running, the displacement
        over the frame's steps (see ``advance``); when nothing stepped (paused, or a body was just
        added/removed), read through the body handles once per change of the world -- that is the
        only case that touches Python objects per body, and it does not repeat every frame."""
        w = self.editor.world
        version = self.editor.doc.history.version
        if self._vel_key is not None and self._vel_key[0] == "stepped" and \
                self._vel_key[1:] == (version, w.steps, len(rd.ids)):
            return self.velocities
        key = ("handles", version, w.steps, rd.ids.tobytes())
        if key != self._vel_key or self.velocities is None:
            self.velocities = np.array([b.velocity for b in w.bodies], dtype=np.float64).reshape(-1, 2)
            self._vel_key = key
        return self.velocities

    def quadtree_cells(self, on_error):
        """``world.quadtree_cells()`` for the overlay (Q).  It shares the broad phase's scratch
        buffers with stepping, so it runs under the physics lock; while a background compile holds
        the lock, the last cells are drawn again.  ``on_error(exc)`` turns the overlay off."""
        if self.lock.acquire(blocking=False):
            try:
                self.quadtree = self.editor.world.quadtree_cells()
            except Exception as exc:  # noqa: BLE001  (a debug overlay must not take the sandbox down)
                on_error(exc)
            finally:
                self.lock.release()
        return self.quadtree
