"""Live solver comparison: the open scene cloned into one or more other modes (or the same mode
with other settings), stepped in lockstep with the main world, with each lane's step time and
error measures sampled for plotting together.

The rivals are copies made through the public API (``document.snapshot`` / ``restore``), so a
comparison never touches the edited world.  Any edit of the scene (a new history version or a new
document) restarts the rivals from the main world's state at that moment: the lanes always start
from the same state, and "drift from main" measures what the modes do differently from there.
"""
from __future__ import annotations

import math
import time

import numpy as np

import physics
from physics import options

from . import compile_units
from .document import restore, snapshot
from .stats import Stats, deepest

#: lane colours (RGBA): the main world, then the rivals (ghost outlines, split panes, plot lines)
LANE_COLORS = ((0.36, 0.62, 0.95, 1.0), (1.0, 0.60, 0.22, 1.0), (0.45, 0.92, 0.55, 1.0),
               (1.0, 0.40, 0.65, 1.0))
MAX_RIVALS = len(LANE_COLORS) - 1
MAX_CATCH_UP = 8        # steps a rival may take in one frame to catch up with the main world
PEN_EVERY = 6           # frames between penetration samples of each lane (world.contact_depths())


class LaneStats(Stats):
    """Per-frame samples of one lane: world time (s), step time (ms/step), energy drift (J, total
    energy minus its value when the lane started), deepest penetration (m) and the RMS distance of
    the dynamic bodies' centres of mass from the main world's (m)."""

    KEYS = ("t", "step_ms", "energy", "pen", "drift")


class Lane:
    """One world of the comparison: ``label`` (what it runs), ``world``, ``color`` (RGBA) and its
    ``stats``.  ``solver``/``integrator``/``settings`` are what the user chose for it."""

    def __init__(self, label, world, color, solver, integrator):
        self.label = label
        self.world = world
        self.color = color
        self.solver = solver
        self.integrator = integrator
        self.stats = LaneStats()
        self.e0 = total_energy(world)
        self.step_ms = 0.0
        self.pen = 0.0
        self.behind = 0          # steps this rival still owes the main world
        self.waiting = ""        # why it is not stepping (its kernels are compiling), or ''


def total_energy(world) -> float:
    """Kinetic + potential energy (J)."""
    return world.kinetic_energy() + world.potential_energy()


def max_depth(world) -> float:
    """The deepest touching contact of the last step (m, >= 0)."""
    return deepest(world.contact_depths())


def rms_drift(a, b, dynamic) -> float:
    """RMS distance (m) between the centres of mass ``a`` and ``b`` (N, 2) over the ``dynamic`` mask."""
    if len(a) != len(b) or not np.any(dynamic):
        return math.nan
    d = a[dynamic] - b[dynamic]
    return float(np.sqrt(np.mean(np.einsum("ij,ij->i", d, d))))


class Comparison:
    """The comparison of the sandbox ``app``'s world with rivals.  ``specs`` lists the rivals as
    (solver, integrator, settings dict); ``view`` is "ghost" (rivals drawn as outlines over the
    scene) or "split" (the first rival in a pane right of the scene).  ``active`` while running."""

    VIEWS = ("ghost", "split")

    def __init__(self, app):
        self.app = app
        self.specs: list[tuple[str, str, dict]] = []
        self.lanes: list[Lane] = []          # the rivals
        self.main = LaneStats()              # the main world's samples (drift is 0 by definition)
        self.main_e0 = 0.0
        self.view = "ghost"
        self.active = False
        self._key = None                     # (document, history version) the rivals were cloned at
        self._base_steps = 0                 # main world steps when the rivals were cloned
        self._last_steps = 0                 # main world steps at the last sample
        self._frame = 0
        self.main_pen = 0.0
        self.restarts = 0

    # -- starting and stopping ---------------------------------------------------------
    def check_spec(self, solver, integrator, settings=None):
        """ValueError naming the field if a rival's mode is not one the world knows."""
        if solver not in options.SOLVERS:
            raise ValueError(f"solver: unknown mode {solver!r}; choose one of {list(options.SOLVERS)}")
        if integrator not in options.INTEGRATORS:
            raise ValueError(f"integrator: unknown {integrator!r}; choose one of {list(options.INTEGRATORS)}")
        return solver, integrator, dict(settings or {})

    def start(self, specs):
        """Compare the main world with rivals ``specs`` [(solver, integrator, settings)] (1 to
        MAX_RIVALS); raises ValueError naming the bad field, with nothing started."""
        specs = [self.check_spec(*s) for s in specs]
        if not 1 <= len(specs) <= MAX_RIVALS:
            raise ValueError(f"rivals: choose 1 to {MAX_RIVALS} modes to compare with (got {len(specs)})")
        self.specs = specs
        self.active = True
        self.restart()

    def stop(self):
        split = self.active and self.view == "split"
        self.active = False
        self.lanes = []
        self._key = None
        if split:         # split view framed the scene in its left column: the whole free area again
            self.app.fit()

    def restart(self):
        """Clone the rivals from the main world's current state; the samples start again."""
        w = self.app.world
        snap = snapshot(w, self.app.editor.tool_joints)
        self.lanes = []
        for k, (solver, integ, settings) in enumerate(self.specs):
            snap["solver"] = solver
            rival = restore(snap)
            rival.integrator = integ
            if settings:
                rival.settings_for(solver).update(settings)
            label = lane_label(solver, integ, settings, w)
            self.lanes.append(Lane(label, rival, LANE_COLORS[k + 1], solver, integ))
            self.app.warmup.prioritize(solver, integ, compile_units.broadphase_of(rival))
        self.main = LaneStats()
        self.main_e0 = total_energy(w)
        self._base_steps = self._last_steps = w.steps
        self._key = self._doc_key()
        self.restarts += 1

    def _doc_key(self):
        doc = self.app.editor.doc
        return id(doc), doc.history.version

    def set_setting(self, lane, name, value):
        """Change one solver setting of a rival live (ValueError from the core names the field)."""
        lane.world.settings_for(lane.solver)[name] = value
        k = self.lanes.index(lane)
        solver, integ, settings = self.specs[k]
        settings = dict(settings, **{name: value})
        self.specs[k] = (solver, integ, settings)
        lane.label = lane_label(solver, integ, settings, self.app.world)

    # -- every frame ----------------------------------------------------------------------
    def update(self, phys_ms: float, steps: int):
        """After the main world stepped ``steps`` times in ``phys_ms``: step each rival as many
        times as the main world has stepped since the rivals were cloned (at most MAX_CATCH_UP a
        frame), then sample every lane."""
        if not self.active:
            return
        if self._key != self._doc_key():
            self.restart()
        w = self.app.world
        owed_total = w.steps - self._base_steps
        stepped = w.steps != self._last_steps       # (a step can be skipped while kernels compile)
        self._last_steps = w.steps
        for lane in self.lanes:
            stepped |= self._catch_up(lane, owed_total)
        if not stepped:
            return
        self._frame += 1
        sample_pen = self._frame % PEN_EVERY == 1
        rd = w.render_data()
        dynamic = rd.kind == 0
        centers = rd.center.copy()
        if sample_pen:
            self.main_pen = max_depth(w)
        main_ms = phys_ms / steps if steps and phys_ms else float(self.main.get("step_ms")[-1:].sum())
        self.main.add(t=w.time, step_ms=main_ms, energy=total_energy(w) - self.main_e0,
                      pen=self.main_pen, drift=0.0)
        for lane in self.lanes:
            if sample_pen:
                lane.pen = max_depth(lane.world)
            lrd = lane.world.render_data()
            lane.stats.add(t=w.time, step_ms=lane.step_ms, energy=total_energy(lane.world) - lane.e0,
                           pen=lane.pen, drift=rms_drift(centers, lrd.center, dynamic))

    def _catch_up(self, lane, owed_total) -> bool:
        """Step ``lane`` towards ``owed_total`` steps under the physics lock; True if it stepped."""
        owed = owed_total - lane.world.steps
        lane.behind = max(0, owed)
        if owed <= 0:
            return False
        warm = self.app.warmup
        bp = compile_units.broadphase_of(lane.world)
        if not warm.can_step(lane.solver, lane.integrator, bp):
            warm.prioritize(lane.solver, lane.integrator, bp)
            lane.waiting = f"compiling {lane.solver} ({lane.integrator}) ..."
            return False
        narrow = compile_units.narrow_unit(lane.world)
        if not warm.narrow_ready(narrow):
            warm.want_unit(narrow)
            lane.waiting = "compiling the narrow phase for these shapes ..."
            return False
        if lane.world.joints and not warm.joints_ready(lane.solver, lane.integrator):
            warm.want_unit(compile_units.joints_unit(lane.solver, lane.integrator))
            lane.waiting = f"compiling the joints of {lane.solver} ({lane.integrator}) ..."
            return False
        lock = self.app.sim.lock
        if not lock.acquire(blocking=False):
            lane.waiting = "compiling kernels ..."
            return False
        lane.waiting = ""
        n = min(owed, MAX_CATCH_UP)
        t0 = time.perf_counter()
        try:
            for _ in range(n):
                lane.world.step(self.app.world.dt)
        except physics.SimulationError as exc:
            self.app.notices.notify(f"comparison: {lane.label} failed ({exc}); it is left out", error=True)
            self.lanes.remove(lane)
            return False
        finally:
            lock.release()
        lane.step_ms = (time.perf_counter() - t0) * 1e3 / n
        lane.behind = owed - n
        return True

    def describe(self) -> dict:
        """What the comparison shows (for the status file): lanes, their last samples."""
        def last(s, k):
            v = s.get(k)
            return float(v[-1]) if len(v) else None
        lanes = [{"label": "main", "n": self.main.n, "steps": self.app.world.steps - self._base_steps, **{k: last(self.main, k) for k in LaneStats.KEYS[1:]}}]
        for ln in self.lanes:
            lanes.append({"label": ln.label, "n": ln.stats.n, "steps": ln.world.steps, "behind": ln.behind,
                          "waiting": ln.waiting, "solver": ln.solver,
                          **{k: last(ln.stats, k) for k in LaneStats.KEYS[1:]}})
        return {"active": self.active, "view": self.view, "lanes": lanes, "restarts": self.restarts}


def lane_label(solver, integrator, settings, main_world) -> str:
    """A short name for a rival: its mode, the integrator if it is not the main one's, the
    settings that differ from the defaults."""
    parts = [solver]
    if integrator != main_world.integrator:
        parts.append(integrator)
    parts += [f"{k}={v:g}" if isinstance(v, float) else f"{k}={v}" for k, v in sorted(settings.items())]
    return " ".join(parts)
