"""The step, assembled from the stages a world needs.

collide (geometry -> broad phase -> narrow phase) -> solver mode (forces,
contacts, springs, integration) -> islands/sleep -> finite check.  Stages a
world does not need are not run: no collision stages without a pair that
can interact, no sleep update with sleeping off, nothing at all while every
body sleeps.  ``info`` lists what will run.
"""
from __future__ import annotations

import numpy as np

from .checkpoint import Checkpoint
from .errors import SimulationError
from .geometry import update_geometry
from .islands import Islands
from .step_frame import begin_step, end_step
from .store import DYNAMIC, KIND_NAMES, STATIC


class Pipeline:
    def __init__(self):
        self._pairs = np.zeros((256, 2), dtype=np.int32)
        self.npairs = 0
        self._checkpoint = Checkpoint()
        self._islands = Islands()
        self.n_awake = -1  # unknown: run everything
        self.last_broadphase = ""

    def invalidate(self) -> None:
        """Something was edited: the next step runs in full."""
        self.n_awake = -1

    # -- stages ---------------------------------------------------------
    def refresh_geometry(self, world, dt: float = 0.0) -> None:
        update_geometry(world._bodies.view, world._verts.view, world._bodies.n, dt, world.speculative_distance)

    def collide(self, world, dt: float, geometry: bool = True) -> None:
        from . import broadphase, narrowphase
        B = world._bodies.view
        n = world._bodies.n
        if geometry:
            self.refresh_geometry(world, dt)
        self.npairs, self._pairs = broadphase.find_pairs(B, n, world.broadphase, self._pairs)
        narrowphase.collide(B, world._verts.view, self._pairs, self.npairs, world._contacts,
                            world.narrowphase, dt, world.speculative_distance)

    def solve(self, world, dt: float) -> None:
        world._mode.step(world, dt, world._mode_settings[world.solver])

    def sleep(self, world, dt: float) -> None:
        if world.sleeping:
            self.n_awake = self._islands.update(world, dt)
        else:
            self.n_awake = -1

    STAGES = ("collide", "solve", "sleep")

    # -- the step -------------------------------------------------------
    def step(self, world, dt: float) -> None:
        n = world._bodies.n
        if n == 0 or (self.n_awake == 0 and world.sleeping):
            world.time += dt
            world.steps += 1
            return
        B = world._bodies.view
        ck = self._checkpoint
        ck.ensure(n)
        begin_step(B, world._verts.view, n, dt, world.speculative_distance, ck.X, ck.Q, ck.V, ck.W)
        stage = "collide"
        try:
            self.collide(world, dt, geometry=False)
            stage = "solve"
            self.solve(world, dt)
            stage = "sleep"
            self.sleep(world, dt)
        except SimulationError as err:
            # a stage refused the step (e.g. an explicit integrator that cannot be stable)
            self._revert(world)
            err.stage = err.stage or stage
            world.fault = err
            raise
        k = end_step(B, n, ck.bad)
        if k:
            self._fail(world, dt, ck.slots(k))
        world.time += dt
        world.steps += 1
        world.fault = None

    def _fail(self, world, dt: float, bad: list[int]) -> None:
        """Revert, replay stage by stage to find the culprit, revert again, report."""
        B = world._bodies.view
        n = world._bodies.n
        self._checkpoint.restore(B, n)
        stage = "?"
        for name in self.STAGES:
            try:
                getattr(self, name)(world, dt)
            except SimulationError:
                stage = name
                break
            if self._checkpoint.nonfinite(B, n):
                stage = name
                break
        self._revert(world)
        # static bodies only turn non-finite through 0 * inf; name the moving culprits first
        moving = [s for s in bad if B.kind[s] != STATIC]
        names = [world._handles[int(B.id[s])].name or f"#{int(B.id[s])}" for s in (moving or bad)]
        err = SimulationError(
            f"step at t={world.time:.4f} s produced non-finite values in {len(names)} bod"
            f"{'y' if len(names) == 1 else 'ies'} ({', '.join(names[:8])}) during the '{stage}' stage "
            f"of solver '{world.solver}'; the world was reverted to the state before the step",
            bodies=names, stage=stage)
        world.fault = err
        raise err

    def _revert(self, world) -> None:
        """Back to the state before the step, without its user forces and contact impulses:
        kept, they (and the non-finite impulses warm starting would re-apply) would fail every
        later step too."""
        B = world._bodies.view
        n = world._bodies.n
        self._checkpoint.restore(B, n)
        B.f[:n] = 0.0
        B.tau[:n] = 0.0
        c = world._contacts
        for tab in (c.cur, c.prev):
            tab.jn[:] = 0.0
            tab.jt[:] = 0.0
        world.wake_all()

    # -- description ----------------------------------------------------
    def info(self, world) -> dict:
        from . import broadphase
        n = world._bodies.n
        B = world._bodies.view
        kinds = {k: int(np.sum(B.kind[:n] == v)) for v, k in KIND_NAMES.items()}
        awake = int(np.sum((B.awake[:n] == 1) & (B.kind[:n] == DYNAMIC)))
        stages = []
        if n:
            bp = broadphase.resolve_method(world.broadphase, n) if hasattr(broadphase, "resolve_method") \
                else world.broadphase
            stages += ["geometry", f"broadphase:{bp}", f"narrowphase:{world.narrowphase}"]
            stages += list(world._mode.stages(world))
            if world.sleeping:
                stages.append("islands/sleep")
            stages.append("finite_check")
        return {
            "bodies": n, **kinds, "awake": awake, "springs": world._springs.n,
            "contacts": world._contacts.n, "solver": world.solver, "integrator": world.integrator,
            "settings": dict(world._mode_settings[world.solver]), "sleeping": world.sleeping,
            "stages": stages,
        }
