"""One run of a scene under one candidate's settings: what the tuner measures.

A case is plain data (the scene as parsed JSON and a ``Candidate``), never a
live World, so it runs the same in this process or on any Dask worker, and
gives the same numbers there (the physics is deterministic).  The run records
the state at fixed *times* (not steps), so candidates with different time
steps are compared at the same instants.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from ..errors import SimulationError

# the dt multiples a candidate may use: the sample times must fall on whole steps of each
DT_FACTORS = (0.125, 0.25, 0.5, 1.0, 2.0)
SHORT = 0.25     # s: a run this short is timed again (_replay), REPLAYS more times
REPLAYS = 2


@dataclass(frozen=True)
class Candidate:
    """A solver mode, some of its declared settings (the rest as the scene has them), an
    integrator (None: the scene's) and the time step as a multiple of the scene's (DT_FACTORS)."""

    solver: str
    settings: tuple = ()          # ((name, value), ...), sorted: hashable and picklable
    dt_factor: float = 1.0
    integrator: str | None = None

    @property
    def key(self) -> str:
        """A short unique label, e.g. ``soft_step substeps=8 dt x0.5``."""
        parts = [self.solver] + [f"{k}={_word(v)}" for k, v in self.settings]
        if self.integrator:
            parts.append(f"integrator={self.integrator}")
        if self.dt_factor != 1.0:
            parts.append(f"dt x{self.dt_factor:g}")
        return " ".join(parts)

    def with_settings(self, **kw) -> "Candidate":
        """This candidate with some settings replaced (dt_factor/integrator too)."""
        s = dict(self.settings)
        dt = kw.pop("dt_factor", self.dt_factor)
        integ = kw.pop("integrator", self.integrator)
        s.update(kw)
        return Candidate(self.solver, tuple(sorted(s.items())), dt, integ)


def _word(v) -> str:
    return ("on" if v else "off") if isinstance(v, bool) else f"{v:g}" if isinstance(v, float) else str(v)


@dataclass
class Run:
    """What one run recorded: positions (K, n, 2, m) and angles (K, n, rad) of the dynamic bodies
    at the K sample times, kinetic and potential energy (K, J), speeds (K, n, m/s), the deepest contact seen at a sample (m), the
    CPU seconds this thread spent in ``world.step`` (sampling excluded: a rank, not a benchmark), and
    the error if a step was refused.
    ``links`` (K, m, m): each spring's length, then each joint's anchor gap |anchor_a - anchor_b|,
    at each sample; ``pins`` (m,): which of them should be 0 (revolute and weld joints)."""

    key: str
    positions: np.ndarray
    angles: np.ndarray
    kinetic: np.ndarray
    potential: np.ndarray
    speeds: np.ndarray
    depth: float
    seconds: float
    steps: int
    error: str | None = None
    sizes: np.ndarray = field(default_factory=lambda: np.zeros(0))
    links: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    pins: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))

    @property
    def energy(self) -> np.ndarray:
        """Total energy at each sample (J)."""
        return self.kinetic + self.potential


def body_sizes(world) -> np.ndarray:
    """Each dynamic body's radius about its centre (m): scales angle errors to metres."""
    out = []
    for b in world.bodies:
        if b.kind != "dynamic":
            continue
        s = b.shape
        if hasattr(s, "vertices"):
            out.append(float(np.max(np.hypot(*(np.asarray(s.vertices) - s.centroid).T))))
        else:
            out.append(float(s.radius + np.hypot(*s.offset)))
    return np.asarray(out)


#: joint kinds whose two anchors coincide when the joint holds (their gap is the position error)
PIN_KINDS = ("revolute", "weld")


def pin_mask(world) -> np.ndarray:
    """Which of ``links``' entries (springs first, then joints) should be 0: the pin joints."""
    return np.array([False] * len(world.springs) + [j.kind in PIN_KINDS for j in world.joints], dtype=bool)


def links(world) -> list[float]:
    """Each spring's length, then each joint's anchor gap (m): the constraint state sampled."""
    out = [s.length for s in world.springs]
    for j in world.joints:
        (ax, ay), (bx, by) = j.anchor_a, j.anchor_b
        out.append(math.hypot(ax - bx, ay - by))
    return out


def build(scene: dict, cand: Candidate):
    """A World from scene data with ``cand`` applied (ValueError for a setting the mode refuses)."""
    from ..scene import scene_from_dict
    world = scene_from_dict(scene, source="<tune case>")
    if world.solver != cand.solver:
        world.solver = cand.solver
    world.settings.update(dict(cand.settings))
    if cand.integrator:
        world.integrator = cand.integrator
    world.dt = world.dt * cand.dt_factor
    return world


def run_case(scene: dict, cand: Candidate, steps: int, stride: int) -> Run:
    """Run ``scene`` under ``cand`` for the time of ``steps`` scene steps, sampling every ``stride``
    scene steps (``stride`` must be a multiple of 1/dt_factor's denominator: see DT_FACTORS).

    A refused step (SimulationError) ends the run early: ``error`` says why, the samples stop."""
    try:  # one throwaway step first: kernels compile (or load from cache) outside the timing
        build(scene, cand).step()
    except SimulationError:
        pass
    world = build(scene, cand)
    per_sample = stride / cand.dt_factor
    if abs(per_sample - round(per_sample)) > 1e-9 or round(per_sample) < 1:
        raise ValueError(f"stride {stride} is not a whole number of steps at dt x{cand.dt_factor:g}")
    per_sample = int(round(per_sample))
    dyn = [b for b in world.bodies if b.kind == "dynamic"]
    samples = [_sample(world, dyn)]
    seconds, done, error = 0.0, 0, None
    # CPU seconds of this thread, not wall time: a sweep shares the machine with its other
    # workers (and whatever else runs), and a run that waited for a core did not cost more
    clock = time.thread_time
    for _ in range(steps // stride):
        t0 = clock()
        try:
            for _ in range(per_sample):
                world.step()
                done += 1
        except SimulationError as exc:
            seconds += clock() - t0
            error = str(exc)[:300]
            break
        seconds += clock() - t0
        samples.append(_sample(world, dyn))
    if error is None and seconds < SHORT:
        seconds = min([seconds] + [_replay(scene, cand, done) for _ in range(REPLAYS)])
    x, a, ke, pe, v, d, ln = (np.array(col, dtype=np.float64) for col in zip(*samples))
    k = len(samples)
    return Run(cand.key, x.reshape(k, len(dyn), 2), a.reshape(k, len(dyn)), ke, pe, v.reshape(k, len(dyn)),
               float(np.max(d)), seconds, done, error, body_sizes(world), ln.reshape(k, -1) if ln.size else
               np.zeros((k, 0)), pin_mask(world))


def _replay(scene: dict, cand: Candidate, steps: int) -> float:
    """CPU seconds of ``steps`` steps of the case again, unsampled.  A short run is mostly the
    step's fixed cost, which another process's load on the shared caches moves by more than a
    candidate's sub-steps do; the least of a few runs is the run's own cost."""
    world = build(scene, cand)
    t0 = time.thread_time()
    for _ in range(steps):
        world.step()
    return time.thread_time() - t0


def _sample(world, dyn):
    x = [b.position for b in dyn]
    a = [b.angle for b in dyn]
    v = [math.hypot(*b.velocity) for b in dyn]
    depth = max((c.depth for c in world.contacts()), default=0.0)  # negative: within the slop, apart
    depth = max(depth, 0.0)
    return x, a, world.kinetic_energy(), world.potential_energy(), v, depth, links(world)


def task(cand: Candidate, scene: dict, steps: int, stride: int) -> Run:
    """``run_case`` with the candidate first: the function Sweep.map sends to the workers."""
    return run_case(scene, cand, steps, stride)
