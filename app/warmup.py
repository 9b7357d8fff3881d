"""Compile the physics kernels in a background thread while the window shows progress.

numba compiles on first call; a cold first launch takes tens of seconds.  The
first stages (everything the open scene needs: its solver and integrator with
every broad and narrow phase) gate the simulation.  Other solver modes and
integrators compile on demand, again in the background, when the user
switches to them; the window keeps drawing and simply does not step that
world until its kernels are ready, so it never freezes.  Python threads share
one interpreter lock, so the window throttles its frame rate while a compile
runs (see ``busy``).
"""
from __future__ import annotations

import threading
import time
import traceback

import physics


def _probe_world(solver: str):
    w = physics.World(solver=solver)
    w.add_body(physics.Polygon.box(10, 1), kind="static", position=(0, -0.5))
    w.add_body(physics.Polygon.box(1, 1), position=(0, 0.49))
    w.add_body(physics.Polygon.box(1, 1), position=(0.2, 1.5), angle=0.1)
    w.add_body(physics.Circle(0.4), position=(1.5, 0.45))
    w.add_body(physics.Circle(0.4), position=(1.6, 1.3))
    hexa = w.add_body(physics.Polygon.regular(6, 0.5), position=(-1.5, 0.45))
    w.add_body(physics.Polygon.box(0.5, 0.5), kind="kinematic", position=(-3, 1), velocity=(0.1, 0))
    w.add_spring(hexa, None, anchor_b=(-1.5, 2.0), stiffness=50.0, damping=0.5)
    return w


class Warmup:
    def __init__(self, world, lock: threading.Lock):
        self.lock = lock
        first, integ = world.solver, world.integrator
        self.stages: list[tuple[str, dict]] = []
        for bp in ("brute", "sweep", "quadtree"):
            for npz in ("sat", "gjk"):
                self.stages.append((f"{first}: {bp} + {npz}",
                                    dict(solver=first, broadphase=bp, narrowphase=npz, integrator=integ)))
        self.gate = len(self.stages)   # the scene may run once these are done
        self.done = 0
        self.warmed: set[tuple[str, str]] = set()
        self._cv = threading.Condition()
        self._queue = list(self.stages)
        self._busy = False
        self.label = "starting"
        self.errors: list[str] = []
        self.t0 = time.monotonic()
        self.t_gate = None
        self.thread = threading.Thread(target=self._run, name="kernel-warmup", daemon=True)

    def start(self):
        self.thread.start()
        return self

    def prioritize(self, solver: str, integrator: str) -> None:
        """Compile this mode next (the user just switched to it)."""
        with self._cv:
            if (solver, integrator) in self.warmed:
                return
            if any(s[1]["solver"] == solver and s[1]["integrator"] == integrator for s in self._queue):
                return
            self._queue.append((f"{solver}: {integrator}", dict(solver=solver, integrator=integrator)))
            self._cv.notify()

    def can_step(self, solver: str, integrator: str) -> bool:
        return self.ready and (solver, integrator) in self.warmed

    def _run(self):
        while True:
            with self._cv:
                while not self._queue:
                    self._busy = False
                    self._cv.wait()
                label, cfg = self._queue.pop(0)
                self._busy = True
            self.label = label
            try:
                with self.lock:
                    w = _probe_world(cfg["solver"])
                    for k, v in cfg.items():
                        if k != "solver":
                            setattr(w, k, v)
                    for _ in range(3):
                        w.step()
                    w.render_data()
                    w.quadtree_cells()
                    w.query_point((0.0, 0.5))
                    w.contacts()
            except Exception as exc:  # noqa: BLE001  (a broken mode must not stop the others)
                self.errors.append(f"{label}: {exc}")
                traceback.print_exc()
            with self._cv:
                self.warmed.add((cfg["solver"], cfg["integrator"]))
                self.done += 1
                if self.done == self.gate:
                    self.t_gate = time.monotonic() - self.t0
                if not self._queue:
                    self._busy = False

    @property
    def ready(self) -> bool:
        """The open scene can run (its kernels are compiled)."""
        return self.done >= self.gate

    @property
    def busy(self) -> bool:
        return self._busy or bool(self._queue)

    @property
    def finished(self) -> bool:
        return self.ready and not self.busy

    def progress(self):
        return min(1.0, self.done / max(1, self.gate)), self.label

    def elapsed(self) -> float:
        return time.monotonic() - self.t0
