"""Run one fuzz case and judge it against the invariants.

Invariants (issue 20): (1) only the documented errors -- ValueError while building (bad input,
e.g. a density that gives no finite mass) and SimulationError from a step, naming its stage
(one of STAGES) with ``world.fault`` set to it; anything else is a **crash**; (2) never a
non-finite state or energy after an accepted step (**silent non-finite**); (3) the total energy
(kinetic + gravity from the start + springs, computed here: energy.py) after an accepted step
never exceeds the stated bound of physics/step/energy_guard.py (EnergyBound), unless a motor or
mouse joint drives the world (**energy gain**: the guard should have refused the step); (4) no
step hangs: a case over CASE_SECONDS is **slow**; memory is reported as the process's peak RSS
(world.max_pairs bounds what a step allocates).  Each case also reports ``gain``, its largest
accepted (E - E0) / starting energy scale, and ``gain_mode``, the mode that stepped to it.
"""
from __future__ import annotations

import math
import random
import time
import traceback

import numpy as np

import physics
from physics.errors import SimulationError
from .energy import EnergyBound
from .worlds import build

STAGES = {"begin", "broadphase", "collide", "solve", "sleep"}
CASE_SECONDS = 60.0
WARM_CASES = 40  # warm-up cases of another seed (base -1), untimed
BAD = ("crash", "silent_nonfinite", "energy_gain", "slow")


def reason(exc: SimulationError) -> str:
    """Why a step was refused, from its message: energy guard, sub-steps, pairs, non-finite."""
    text = str(exc)
    for key, what in (("total energy", "energy_guard"), ("sub-steps", "substeps"),
                      ("max_pairs", "pairs"), ("non-finite", "nonfinite"), ("contact rows", "contacts")):
        if key in text:
            return what
    return "other"


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
        d = w.add_body(physics.Polygon.box(0.5, 0.5), position=(3.0, 2.0))
        w.add_joint("revolute", a, d, anchor=(1.5, 1.5))
        w.add_joint("distance", d, None, anchor_b=(3.0, 4.0), spring_hertz=2.0)
        w.add_joint("mouse", c, None, target=(0.0, 3.0))
        for k in range(3):
            try:
                w.step()
            except SimulationError:
                pass
        del g
    for i in range(WARM_CASES):  # the paths random worlds take (joint kinds, sleeping, switches)
        run_case(i, base=-1, seconds=math.inf)


def run_case(seed: int, base: int = 0, seconds: float = CASE_SECONDS) -> dict:
    """One case from random.Random(f"world:{base}:{seed}"); returns {outcome, detail, mode, steps};
    ``seconds``: time after which the case counts as slow."""
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
    out = {"mode": w.solver, "dt": w.dt, "bodies": len(w.bodies), "springs": len(w.springs),
           "joints": len(w.joints), "driven": plan.driven, "overlapping": plan.overlapping, "gain": 0.0}
    bound = EnergyBound(w)
    for k in range(plan.steps):
        if k == plan.switch_at:
            w.solver = plan.switch_to
        try:
            w.step()
        except SimulationError as exc:
            ok = exc.stage in STAGES and w.fault is exc and finite_state(w)
            return {**out, "outcome": "refused" if ok else "crash", "stage": exc.stage, "steps": k,
                    "reason": reason(exc), "detail": str(exc)[:200]}
        except Exception as exc:  # noqa: BLE001
            return {**out, "outcome": "crash", "steps": k, "detail": f"{type(exc).__name__}: {exc}"[:300],
                    "trace": traceback.format_exc()[-800:]}
        e, scale = bound.energy(w)
        if not finite_state(w) or not math.isfinite(e):
            return {**out, "outcome": "silent_nonfinite", "steps": k + 1, "detail": f"energy {e}"}
        limit = bound.limit(w, e, scale)
        out.update(gain=bound.gain, gain_mode=bound.gain_mode)  # (E - E0) / starting scale, largest so far
        if not plan.driven and e - limit > 1e-9 * (scale + bound.s0 + abs(bound.e0)):
            return {**out, "outcome": "energy_gain", "steps": k + 1,
                    "detail": f"energy {e:.4g} J > bound {limit:.4g} J at step {k + 1}"}
        if time.perf_counter() - t0 > seconds:
            return {**out, "outcome": "slow", "steps": k + 1, "detail": f"over {seconds} s"}
    return {**out, "outcome": "ok", "steps": plan.steps}
