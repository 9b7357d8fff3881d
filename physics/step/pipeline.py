"""The step, assembled from the stages a world needs.

One step, as data flowing through it (docs/internals.md):

    begin (save the last finite state, world geometry and AABBs)
      -> broad phase (pairs of overlapping AABBs)
      -> narrow phase (manifolds; per-point state carried from the last step)
      -> solve (the solver mode: forces, contacts, springs, integration)
      -> islands (sleep)
      -> finish (finite check, then the energy guard: revert and report, or clear user forces)
      -> events (an accepted step's touching and sensor-overlap sets: events.py)

The broad phase's pairs pass the events stage's filter (events.py: sensor pairs split off in a
world with sensors and tested after the narrow phase, the user's pair filter when set).

Stages a world does not need are not run: nothing at all while every body
sleeps, no sleep update with sleeping off.  Every stage reads the step context
(physics/step/context.py) and the world's store; the solver mode also its
parameter record.  ``World.profile`` is the last step's seconds per stage.
"""
from __future__ import annotations

import numpy as np

from .. import options, solvers
from ..collision import broadphase, narrowphase
from ..constraints.joints.work import joint_work
from ..errors import SimulationError
from ..geometry.transform import update_geometry
from ..store import DYNAMIC, KIND_NAMES, STATIC
from ..store.slot_list import ALL
from ..threads import FORKED
from .checkpoint import Checkpoint
from .energy_guard import EnergyGuard
from .events import StepEvents
from .context import ModeParams, StepContext
from .frame import begin_step_flat, end_step_flat
from .islands import Islands
from .one_call import OneCall
from .profile import StepProfile


class Pipeline:
    def __init__(self):
        self._pairs = np.zeros((256, 2), dtype=np.int32)
        self.npairs = 0
        self._checkpoint = Checkpoint()
        self._guard = EnergyGuard()
        self._islands = Islands()
        self.events = StepEvents()
        self.ctx = StepContext()
        self.profile = StepProfile()
        self._params: dict[str, ModeParams] = {}
        self.n_awake = -1  # unknown: run everything
        self.edits = 0  # edits so far (the query cache's key: physics/queries/cache.py)
        self.dirty = True  # the world's settings changed: refresh the context's settings
        self._dt = None
        self._threads = 0  # the thread count last written into the context
        self._push_speed = None  # the context's push-out speed cap (the energy guard's allowance)
        self._no_keys = np.zeros(0, np.int64)
        self.one_call = OneCall()  # the step as one compiled call, where the mode has a driver
        self.python_steps = 0  # narrow phases run from Python (the driver's pack is then rebuilt)

    def invalidate(self) -> None:
        """Something was edited: the next step runs in full (and queries rebuild their tree)."""
        self.n_awake = -1
        self.edits += 1

    # -- the context ----------------------------------------------------
    def _refresh(self, world, dt: float) -> None:
        """Write this step's counts and settings into the step context."""
        ctx = self.ctx
        store = world._store
        ctx.set("step", world.steps)
        ctx.set("n", store.bodies.n)
        ctx.set("ns", store.springs.n)
        ctx.set("nj", store.joints.n)
        ctx.set("nc", store.contacts.n)
        self.refresh_settings(world, dt)

    def refresh_settings(self, world, dt: float) -> None:
        """Write the step length and, when they changed, the world's settings into the context;
        the thread count every step (a forked child runs one: threads.usable)."""
        ctx = self.ctx
        t = 1 if FORKED[0] else world._threads  # (threads.usable, inline: this runs at every step)
        if t != self._threads:
            ctx.set("threads", t)
            self._threads = t
        if dt != self._dt:
            ctx.set("dt", dt)
            ctx.set("inv_dt", 1.0 / dt)
            self._dt = dt
        if self.dirty:
            g = world._gravity
            ctx.set("gx", g[0])
            ctx.set("gy", g[1])
            ctx.set("spec", world.speculative_distance)
            ctx.set("slop", world.linear_slop)
            ctx.set("sleep_linear", world.sleep_linear)
            ctx.set("sleep_angular", world.sleep_angular)
            ctx.set("time_to_sleep", world.time_to_sleep)
            ctx.set("integrator", options.INTEGRATORS.index(world.integrator))
            ctx.set("narrowphase", options.NARROWPHASES.index(world.narrowphase))
            self.dirty = False

    def params(self, world) -> ModeParams:
        """The current mode's parameter record, reloaded when one of its settings changed; the
        context's ``push_speed`` is the mode's (SolverMode.push_speed)."""
        mode = world._mode
        par = self._params.get(mode.name)
        if par is None:
            par = self._params[mode.name] = ModeParams(mode.settings, mode.derived, mode.record)
        vals = world._settings_store(mode.name)
        if vals.fitted_at != self.edits:  # (self.fitted, inline: this runs at every step)
            self.fitted(world, mode)
        if par.version != vals.version:
            eff = vals.effective()
            par.load(eff, vals.version)
            par.push_speed = mode.push_speed(eff)
        if par.push_speed != self._push_speed:  # another mode, or its setting changed
            self.ctx.set("push_speed", par.push_speed)
            self._push_speed = par.push_speed
        return par

    def fitted(self, world, mode):
        """The mode's values in ``world``, with what the scene calls for (SolverMode.fit) asked
        again after each edit."""
        vals = world._settings_store(mode.name)
        if vals.fitted_at != self.edits:
            vals.fit(mode.fit(world))
            vals.fitted_at = self.edits
        return vals

    # -- stages ---------------------------------------------------------
    def refresh_geometry(self, world, dt: float = 0.0) -> None:
        s = world._store
        update_geometry(s.bodies.view, s.fixtures.view, s.verts.view, s.bodies.n, s.fixtures.n, dt,
                        world.speculative_distance, True, None, ALL, s.fixtures.n)

    def collide(self, world, dt: float, geometry: bool = True) -> None:
        s = world._store
        self.python_steps += 1
        if geometry:
            self.refresh_geometry(world, dt)
        F = s.fixtures.view
        self.npairs, self._pairs = broadphase.find_pairs(F, s.fixtures.n, world.broadphase, self._pairs,
                                                         world.max_pairs, s.fixtures.arrays.flat)
        keys = self._no_keys
        if s.joints.n:  # joined bodies do not collide (unless the joint says so)
            work = joint_work(s)
            work.update(s)
            keys = work.exclude
        # fixtures of one body, filtered pairs and joined bodies never collide; sensor pairs
        # and the user's pair filter go their own way (events.py)
        self.npairs = self.events.pairs(world, s.fixtures, self._pairs, self.npairs, keys)
        self.profile.stamp("broadphase")
        narrowphase.collide(self.ctx, s.bodies.arrays, s.fixtures.arrays, s.verts.arrays, self._pairs, self.npairs,
                            s.contacts, world.max_pairs)
        self.events.sense(self.ctx, s)
        self.ctx.set("nc", s.contacts.n)
        self.profile.stamp("narrowphase")

    def solve(self, world, dt: float) -> None:
        par = self.params(world)
        world._mode.derive(self.ctx, par, world._store)
        world._mode.step(self.ctx, par, world._store)
        self.profile.stamp("solve")

    def sleep(self, world, dt: float) -> None:
        if world.sleeping:
            self.n_awake = self._islands.update(self.ctx, world._store)
        else:
            self.n_awake = -1
        self.profile.stamp("islands")

    # -- the step -------------------------------------------------------
    def step(self, world, dt: float) -> None:
        store = world._store
        n = store.bodies.n
        if n == 0 or (self.n_awake == 0 and world.sleeping):
            world._time += dt
            world.steps += 1
            if n == 0:
                self.events.idle(world)
            return
        if self.one_call.step(world, self, dt):
            return
        self.profile.start()
        self._refresh(world, dt)
        guard = self._guard
        self.open_step(world)
        guard.begin(world)
        self.profile.stamp("begin")
        stage = "collide"
        try:
            self.collide(world, dt, geometry=False)
            stage = "solve"
            self.solve(world, dt)
            stage = "sleep"
            self.sleep(world, dt)
        except SimulationError as err:
            # a stage refused the step (e.g. an explicit integrator that cannot be stable)
            self.refuse(world, err, stage)
        except ArithmeticError as exc:
            # Python-side arithmetic of a stage overflowed (a rate or count out of the float
            # range): the step's numbers are not representable, which is a refused step too
            self._revert(world)
            err = SimulationError(f"step at t={world.time:.4f} s: arithmetic failed in the '{stage}' stage "
                                  f"of solver '{world.solver}' ({type(exc).__name__}: {exc}); the world was "
                                  "reverted to the state before the step", stage=stage)
            world.fault = err
            raise err from exc
        k, nt, nb, na = self.close_step(world)
        if k:
            self._fail(world, self._checkpoint.slots(k))
        gained = guard.excess(world, dt)
        if gained is not None:
            self._gained(world, *gained)
        self.profile.stamp("finish")
        self.profile.finish()
        world._time += dt
        world.steps += 1
        world.fault = None
        self.events.commit(world, nt, nb, na)

    def open_step(self, world) -> None:
        """The kernel that opens a step: checkpoint, energy sums, fixture geometry (frame.py)."""
        store = world._store
        ck = self._checkpoint
        ck.ensure(store.bodies.n)
        begin_step_flat(self.ctx.array, *store.bodies.arrays.flat, *store.fixtures.arrays.flat,
                        *store.verts.arrays.flat, store.fixtures.n, ck.X, ck.Q, ck.V, ck.W,
                        *store.springs.arrays.flat, self._guard.start)

    def close_step(self, world):
        """The kernel that closes a step (finite check, energy sums, touch events: frame.py);
        returns (non-finite bodies, touches, began, ended)."""
        store = world._store
        ck = self._checkpoint
        C = store.contacts.cur
        nc = store.contacts.n
        return end_step_flat(self.ctx.array, *store.bodies.arrays.flat, *store.springs.arrays.flat, ck.bad, ck.why,
                             C.a, C.b, nc, ck.cluster, self._guard.end, C.key, C.count, C.depth, C.jn,
                             *self.events.contacts.scratch(nc))

    def refuse(self, world, err, stage: str) -> None:
        """Revert the step and raise ``err`` (a SimulationError) as the ``stage`` stage's."""
        self._revert(world)
        err.stage = err.stage or stage
        world.fault = err
        raise err

    #: the stages that write the bodies' state (x, q, v, w); the others read it (collision) or
    #: only zero velocities (islands), so a non-finite state after the step is theirs
    STATE_STAGES = ("solve",)

    def _fail(self, world, bad: list[int]) -> None:
        """Revert and report a step whose state (or energy) is not finite."""
        store = world._store
        B = store.bodies.view
        energy = self._checkpoint.energy
        n = store.bodies.n
        self._checkpoint.restore(B, n)
        # the saved state itself not finite: it was written past the validated setters
        stage = "begin" if self._checkpoint.nonfinite(B, n, store.springs.view, store.springs.n) \
            else self.STATE_STAGES[-1]
        self._revert(world)
        # static bodies only turn non-finite through 0 * inf; name the moving culprits first
        moving = [s for s in bad if B.kind[s] != STATIC]
        names = [world._handles[int(B.id[s])].name or f"#{int(B.id[s])}" for s in (moving or bad)]
        what = "a non-finite energy (finite state, kinetic or elastic energy beyond 1.8e308 J)" if energy \
            else "non-finite values"
        verb = "started from" if stage == "begin" else "produced"
        err = SimulationError(
            f"step at t={world.time:.4f} s {verb} {what} in {len(names)} bod"
            f"{'y' if len(names) == 1 else 'ies'} ({', '.join(names[:8])}) during the '{stage}' stage "
            f"of solver '{world.solver}'; the world was reverted to the state before the step",
            bodies=names, stage=stage)
        world.fault = err
        raise err

    def _gained(self, world, energy: float, limit: float) -> None:
        """Revert and report a step that gained more energy than the guard allows."""
        self._revert(world)
        err = SimulationError(
            f"step at t={world.time:.4f} s of solver '{world.solver}' raised the total energy to "
            f"{energy:.4g} J, beyond the {limit:.4g} J a world without external input may reach "
            "(physics/step/energy_guard.py; world.energy_guard); the world was reverted to the state "
            "before the step", stage="solve")
        world.fault = err
        raise err

    def _revert(self, world) -> None:
        """Back to the state before the step, without its user forces and contact impulses:
        kept, they (and the non-finite impulses warm starting would re-apply) would fail every
        later step too."""
        store = world._store
        B = store.bodies.view
        n = store.bodies.n
        self._checkpoint.restore(B, n)
        B.f[:n] = 0.0
        B.tau[:n] = 0.0
        store.contacts.forget_impulses()
        world.wake_all()

    # -- description ----------------------------------------------------
    def info(self, world) -> dict:
        store = world._store
        n = store.bodies.n
        B = store.bodies.view
        kinds = {k: int(np.sum(B.kind[:n] == v)) for v, k in KIND_NAMES.items()}
        awake = int(np.sum((B.awake[:n] == 1) & (B.kind[:n] == DYNAMIC)))
        vals = self.fitted(world, world._mode)
        values = vals.effective()
        stages = []
        if n:
            bp = broadphase.resolve(world.broadphase, store.fixtures.n)
            stages += ["geometry", f"broadphase:{bp}", f"narrowphase:{world.narrowphase}"]
            stages += list(world._mode.stages(store, values, world.integrator))
            if world.sleeping:
                stages.append("islands/sleep")
            stages.append("finite_check")
        return {
            "bodies": n, **kinds, "awake": awake, "springs": store.springs.n, "joints": store.joints.n,
            "contacts": store.contacts.n, "solver": world.solver, "integrator": world.integrator,
            "integrator_note": solvers.unused_integrator(world.solver, world.integrator) or "",
            "settings": dict(values), "sleeping": world.sleeping,
            # the settings the world chose from the scene (where the user set none), and why
            "chosen": {k: {"value": v, "why": why} for k, (v, why) in vals.in_force().items()},
            "stages": stages,
        }
