"""``tune``: the fastest solver mode and settings whose error on this scene is within a budget.

1. Reference: soft_step with 8 sub-steps of a quarter of the scene's dt, checked against the same
   at an eighth (twice as fine).  If the two disagree by more than half the budget the scene is
   chaotic (or the reference unconverged) at this length: no trajectory can be trusted, and the
   statistical measures of metrics.statistical stand in, which the result says.
2. Round one (candidates.round_one) and round two (refinements of round one's Pareto front),
   each run as Dask tasks (sweep.Sweep).
3. The choice: the fastest finished candidate with error <= budget (None if there is none).
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, field

from . import candidates as grid
from .metrics import check_budget, check_metric, compare, statistical
from .runs import Candidate, task
from .journal import Journal
from .sweep import Sweep

# samples per run (the stride is rounded so every DT_FACTORS step count is whole)
SAMPLES = 40
MIN_STEPS = 8


@dataclass
class TuneResult:
    """What ``tune`` found: every candidate's row (key, candidate, seconds, error, measures,
    within, front), the Pareto front, the choice (a row, or None if no candidate is within the
    budget), the scene-as-is row, and the reference check (gap, converged, note)."""

    metric: str
    budget: float
    steps: int
    rows: list
    front: list
    choice: dict | None
    baseline: dict
    reference_gap: float
    converged: bool
    note: str
    where: str
    scene_world: dict = field(default_factory=dict)

    @property
    def fragment(self) -> dict | None:
        """The scene file's ``world`` block fields that apply the choice (None without a choice)."""
        if self.choice is None:
            return None
        return world_fragment(self.scene_world, self.choice["candidate"])


def world_fragment(world: dict, cand: Candidate) -> dict:
    """``world`` (a scene's world block) with ``cand`` applied: solver, its settings, dt, integrator."""
    from ..scene import schema as fmt
    w = {**fmt.WORLD_DEFAULTS, **world}
    same = w["solver"] == cand.solver
    out = {"solver": cand.solver, "settings": {**(w["settings"] if same else {}), **dict(cand.settings)},
           "dt": w["dt"] * cand.dt_factor}
    if cand.integrator:
        out["integrator"] = cand.integrator
    return out


def scene_data(source) -> tuple[dict, str]:
    """(checked scene data, a name for messages) from a World, scene data or a scene file path;
    SceneError for a bad file or data."""
    from ..scene import read_scene, scene_from_dict, scene_to_dict
    if isinstance(source, (str, os.PathLike)):
        src = os.fspath(source)
        data = read_scene(src)
        scene_from_dict(data, source=src)
        return data, src
    if isinstance(source, dict):
        scene_from_dict(source)
        return source, "<dict>"
    if hasattr(source, "bodies") and hasattr(source, "settings"):
        return scene_to_dict(source), "<world>"
    raise TypeError(f"tune: expected a World, scene data or a scene file path, got {type(source).__name__}")


def check_steps(steps) -> int:
    """``steps`` as an int >= MIN_STEPS, else ValueError naming it."""
    if isinstance(steps, bool) or not isinstance(steps, int) or steps < MIN_STEPS:
        raise ValueError(f"steps: must be a whole number >= {MIN_STEPS}, got {steps!r}")
    return steps


def stride_for(steps: int) -> int:
    """Scene steps between samples: about steps / SAMPLES, a multiple of 8 (dt x0.125 to x2 whole)."""
    return max(8, 8 * round(steps / SAMPLES / 8))


def tune(source, steps: int = 600, metric: str = "trajectory", budget: float = 0.01, scheduler=None,
         modes=None, progress: bool = True, results=None, resume: bool = False, cancel=None,
         on_progress=None) -> TuneResult:
    """The fastest mode and settings for ``source`` (World, scene data or scene file) whose
    ``metric`` error over ``steps`` scene steps is <= ``budget`` (metres; energy_drift: a fraction).

    ``scheduler``: None (a local Dask cluster), a Dask address, or "inline"; ``modes``: the solver
    modes to search (default all; the scene as it is always runs, as the speed baseline, and is
    chosen only if its mode is among them).  ``results``: a file that receives each finished run as
    it arrives (journal.py); with ``resume`` the runs already in it are not run again.
    ``cancel``: a callable (e.g. ``threading.Event().is_set``) checked between runs; once it returns
    True the search stops with sweep.Cancelled.  ``on_progress(stage, done, total)``: called as
    runs finish (stage "reference", "round 1" or "round 2").
    ValueError names a bad steps, metric (``constraint`` on a scene without springs or joints),
    budget, modes, scheduler or results file; SceneError for a bad scene."""
    metric, budget, steps = check_metric(metric), check_budget(budget), check_steps(steps)
    modes = _check_modes(modes)
    data, _ = scene_data(source)
    if metric == "constraint" and not (data.get("springs") or data.get("joints")):
        raise ValueError("metric: 'constraint' measures springs and joints, and this scene has none; "
                         "choose another metric")
    stride = stride_for(steps)
    steps = max(stride, steps // stride * stride)
    journal = Journal(results, data, steps, stride, resume) if results is not None else None
    try:
        with Sweep(scheduler, progress=progress, cancel=cancel, on_progress=on_progress) as sweep:
            return _search(sweep, journal, data, steps, stride, metric, budget, modes)
    finally:
        if journal is not None:
            journal.close()


def _search(sweep, journal, data, steps, stride, metric, budget, modes) -> TuneResult:
    ref, fine = sweep.map(task, [grid.REFERENCE, grid.FINE], data, steps, stride, desc="reference",
                          journal=journal)
    gap = compare(fine, ref, metric if metric != "penetration" else "trajectory")["error"]
    converged = ref.error is None and fine.error is None and gap <= 0.5 * budget
    score = (lambda r: compare(r, ref, metric)) if converged else (lambda r: statistical(r, ref, metric))
    base = Candidate(data.get("world", {}).get("solver", "soft_step"))
    first = [base] + [c for c in grid.round_one(modes) if c.key != base.key]
    rows = [_row(c, r, score(r), budget) for c, r in
            zip(first, sweep.map(task, first, data, steps, stride, desc="round 1", journal=journal))]
    mine = [r for r in rows if r["candidate"].solver in modes]
    second = [c for c in grid.round_two([r["candidate"] for r in grid.pareto(mine)])
              if c.key not in {r["key"] for r in rows}]
    rows += [_row(c, r, score(r), budget) for c, r in
             zip(second, sweep.map(task, second, data, steps, stride, desc="round 2", journal=journal))]
    where = sweep.where
    front = grid.pareto(rows)
    for r in rows:
        r["front"] = r in front
    ok = [r for r in rows if r["within"] and r["candidate"].solver in modes]  # the scene as is: for speed only
    choice = _cheapest(ok)
    return TuneResult(metric, budget, steps, rows, front, choice, rows[0], gap, converged,
                      _note(converged, gap, metric, budget, ref, fine), where, dict(data.get("world", {})))


#: run times within this fraction of the fastest are a tie: one timed run of a small scene varies
#: by more than that under load, and the deterministic work then decides
TIE = 0.1


def _cheapest(ok: list) -> dict | None:
    """The row to recommend among those within the budget: the fastest, except that among the
    rows timed within TIE of it, the one with the least solver work per simulated second
    (``work``) wins, so that timing noise does not pick a costlier setting."""
    if not ok:
        return None
    fastest = min(r["seconds"] for r in ok)
    ties = [r for r in ok if r["seconds"] <= fastest * (1.0 + TIE)]
    return min(ties, key=lambda r: (work(r["candidate"]), r["seconds"]))


def work(cand: Candidate) -> float:
    """Solver passes per scene step: the sub-steps (or velocity iterations) the candidate runs,
    divided by its time-step factor (half the dt: twice the steps)."""
    decl = grid.declared(cand.solver)
    given = dict(cand.settings)
    for name in ("substeps", "velocity_iterations", "iterations"):
        if name in decl:
            return float(given.get(name, decl[name].default)) / cand.dt_factor
    return 1.0 / cand.dt_factor


def _row(cand: Candidate, run, measures: dict, budget: float) -> dict:
    err = measures["error"]
    return {"key": cand.key, "candidate": cand, "seconds": run.seconds, "error": err, "measures": measures,
            "refused": run.error, "within": run.error is None and math.isfinite(err) and err <= budget}


def _check_modes(modes) -> list[str]:
    from ..options import SOLVERS
    if modes is None:
        return list(SOLVERS)
    modes = [modes] if isinstance(modes, str) else list(modes)
    bad = [m for m in modes if m not in SOLVERS]
    if bad or not modes:
        raise ValueError(f"modes: unknown solver mode(s) {bad or modes!r}; choose from {list(SOLVERS)}")
    return modes


def _note(converged, gap, metric, budget, ref, fine) -> str:
    if ref.error or fine.error:
        return f"the reference run was refused ({ref.error or fine.error}); statistical measures used"
    if converged:
        return (f"reference converged: it and a run twice as fine differ by {gap:.3g} "
                f"(budget {budget:g}); candidates scored against it by {metric}")
    return (f"chaotic or unconverged: the reference and a run twice as fine differ by {gap:.3g}, more "
            f"than half the budget ({budget:g}), so no trajectory is trustworthy; scored instead by "
            "statistical measures (energy gain, penetration, resting drift, pin joints' gaps)")
