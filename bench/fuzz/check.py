"""Run one fuzz case and judge it against the invariants.

Invariants (issue 20): (1) only the documented errors -- ValueError while building (bad input,
e.g. a density that gives no finite mass) and SimulationError from a step, naming its stage
(one of STAGES) with ``world.fault`` set to it; anything else is a **crash**; (2) never a
non-finite state or energy after an accepted step (**silent non-finite**); (3) the total energy
(kinetic + gravity + springs) after an accepted step never exceeds ``energy_bound``, with no
external input (**energy gain**); (4) no step hangs: a case over CASE_SECONDS is **slow**;
memory is reported as the process's peak RSS (world.max_pairs bounds what a step allocates).
"""
from __future__ import annotations

import math
import random
import time
import traceback

import numpy as np

import physics
from physics.errors import SimulationError

from .worlds import build

STAGES = {"begin", "broadphase", "collide", "solve", "sleep"}
CASE_SECONDS = 60.0
#: push-out of bodies created inside each other may add up to 1/2 m (n v_cap)^2 per body
PUSH_SPEED = 10.0
BAD = ("crash", "silent_nonfinite", "energy_gain", "slow")


def energies(w) -> tuple[float, float]:
    """(total energy, its scale: kinetic + springs + |gravity potential|) in J."""
    with np.errstate(all="ignore"):
        ke = w.kinetic_energy()
        pe = w.potential_energy()
        springs = sum(0.5 * s.stiffness * (s.length - s.rest_length) ** 2 for s in w.springs)
    return ke + pe, ke + springs + abs(pe - springs)


def energy_bound(w, overlapping: bool) -> float:
    """The largest total energy a case may reach: E0 plus its own scale (a factor 2 over the
    energy present: symplectic Euler's energy oscillates by O(omega h) <= 1 of it at the seed
    modes' sub-step limit; the explosions found were 1e3..1e24x) plus, for bodies created
    inside each other, the push-out allowance."""
    e0, scale = energies(w)
    extra = 0.0
    if overlapping:
        n = len(w.bodies)
        extra = sum(0.5 * b.mass * (n * PUSH_SPEED) ** 2 for b in w.bodies if b.kind == "dynamic")
    return e0 + scale + extra + 1e-9


def finite_state(w) -> bool:
    st = w.state()
    return all(bool(np.isfinite(st[f]).all()) for f in st.dtype.names
               if np.issubdtype(st.dtype[f].base, np.floating))


def warm_up() -> None:
    """Compile every mode's kernels (contacts, springs, a mode switch) before cases are timed:
    numba's first call of a kernel is compilation, not a hang."""
    for mode in physics.solvers_available():
        w = physics.World(solver=mode)
        g = w.add_body(physics.Polygon.box(10, 1), kind="static")
        a = w.add_body(physics.Polygon.box(1, 1), position=(0, 1.0))
        c = w.add_body(physics.Circle(0.5), position=(0.2, 2.0))
        w.add_spring(a, c, stiffness=1e3)
        w.add_spring(a, None, anchor_b=(0, 3), stiffness=1e7)
        for k in range(3):
            try:
                w.step()
            except SimulationError:
                pass
        del g


def run_case(seed: int, base: int = 0) -> dict:
    """One case from random.Random(f"world:{base}:{seed}"); returns {outcome, detail, mode, steps}."""
    rnd = random.Random(f"world:{base}:{seed}")
    t0 = time.perf_counter()
    try:
        plan = build(rnd)
    except ValueError as exc:
        return {"outcome": "value_error", "detail": str(exc)[:200], "steps": 0}
    except Exception as exc:  # noqa: BLE001 (an undocumented error is the finding)
        return {"outcome": "crash", "detail": f"build: {type(exc).__name__}: {exc}"[:300], "steps": 0,
                "trace": traceback.format_exc()[-800:]}
    w = plan.world
    out = {"mode": w.solver, "dt": w.dt, "bodies": len(w.bodies), "springs": len(w.springs)}
    limit = energy_bound(w, plan.overlapping)
    for k in range(plan.steps):
        if k == plan.switch_at:
            w.solver = plan.switch_to
        try:
            w.step()
        except SimulationError as exc:
            ok = exc.stage in STAGES and w.fault is exc and finite_state(w)
            return {**out, "outcome": "refused" if ok else "crash", "stage": exc.stage, "steps": k,
                    "detail": str(exc)[:200]}
        except Exception as exc:  # noqa: BLE001
            return {**out, "outcome": "crash", "steps": k, "detail": f"{type(exc).__name__}: {exc}"[:300],
                    "trace": traceback.format_exc()[-800:]}
        e, _ = energies(w)
        if not finite_state(w) or not math.isfinite(e):
            return {**out, "outcome": "silent_nonfinite", "steps": k + 1, "detail": f"energy {e}"}
        if e > limit:
            return {**out, "outcome": "energy_gain", "steps": k + 1,
                    "detail": f"energy {e:.4g} J > bound {limit:.4g} J at step {k + 1}"}
        if time.perf_counter() - t0 > CASE_SECONDS:
            return {**out, "outcome": "slow", "steps": k + 1, "detail": f"over {CASE_SECONDS} s"}
    return {**out, "outcome": "ok", "steps": plan.steps}
