"""The probes of the reliability table: a scenario (bench/scenarios/extremes), its judge, the
regime it stands for and the advice the table gives."""
from __future__ import annotations

import time
from dataclasses import dataclass, field

import physics

from ..scenarios import extremes as x
from . import judges as j
from .outcome import FAILED, UNAVAILABLE, Outcome


@dataclass
class Probe:
    """``name`` and ``regime`` (table text), ``measure`` (a scenario: solver -> figures),
    ``judge`` (figures -> Outcome), ``advice`` (the table's last column), ``quick_kw`` (the
    measure's arguments in a --quick run)."""
    name: str
    regime: str
    measure: object
    judge: object
    advice: str
    quick_kw: dict = field(default_factory=dict)


PROBES = [
    Probe("mass ratio: stack", "1000 kg box on a 1 kg box", x.mass_ratio_stack, j.mass_ratio_stack,
          "Sub-stepping is what carries a heavy load on a light body: use soft_step (raise substeps for "
          "larger ratios). sequential_impulse fails here (projected Gauss-Seidel at 1000:1, as in Box2D "
          "2.x; the block solver and 64 velocity iterations do not help)."),
    Probe("mass ratio: spring chain", "1 kg links in a spring chain (k 2e4) carrying 100 kg", x.spring_chain, j.spring_chain,
          "Every mode settles it: soft_step and sequential_impulse solve their stiff springs together "
          "(backward Euler on the whole chain), the seed modes sub-step their explicit springs."),
    Probe("stiff spring", "k = 1e6 N/m on 1 kg at dt = 1/60 (k dt^2/m = 278)", x.stiff_spring, j.stiff_spring,
          "soft_step or sequential_impulse (implicit springs: stable, energy is damped, not gained); an "
          "explicit mode must sub-step or it refuses the step."),
    Probe("speed", "1000 m/s bodies against a 1 cm wall", x.bullets, j.bullets,
          "Modes with speculative contacts (soft_step, sequential_impulse) stop bullets; avoid modes "
          "without continuous collision for fast bodies."),
    Probe("speed: volley", "14 bodies at 1000 m/s, 3 m apart, against a 1 cm wall", x.volley, j.bullets,
          "soft_step or sequential_impulse: pairs that cannot meet within the step get no speculative "
          "rows, so fast neighbours fly past each other."),
    Probe("scale: 1 cm", "five 0.01 m boxes stacked", x.small_stack, j.scaled_stack,
          "soft_step with substeps=16, contact_hertz=120 (sink < 10%, see tests/extremes/test_scale.py); "
          "better, model in metres with bodies >= 0.1 m."),
    Probe("scale: 100 m", "five 100 m boxes stacked", x.large_stack, j.scaled_stack,
          "Large bodies are fine; keep sizes within 0.1..100 m for the default tolerances."),
    Probe("far from origin", "55-box pyramid 10 km from the origin vs at it", x.far_pyramid, j.far_pyramid,
          "Doubles hold at 10 km: soft_step and sequential_impulse match the origin run to 1e-8 mm."),
    Probe("10 000 bodies", "10 000 boxes dropped in a 200 x 50 grid", x.ten_thousand, j.ten_thousand,
          "Use soft_step with sleeping on; cost grows linearly with the number of contacts.",
          quick_kw=dict(count=2000, steps=60)),
    Probe("near-collinear", "extra vertex 1e-7 m off a box edge, stacked three high", x.near_collinear, j.near_collinear,
          "Safe in every mode that held; Polygon.hull drops such vertices if you prefer."),
    Probe("slivers", "1 m x 1 mm boxes (1:1000), dropped, end-on at 10 m/s, stacked", x.slivers, j.slivers,
          "soft_step (sub-steps and rotation cap); give slivers some thickness (>= 1 cm) otherwise."),
    Probe("coincident bodies", "eight boxes created on top of each other", x.coincident, j.coincident,
          "soft_step separates them gently (push_out_speed, default 3 m/s); penalty/hybrid cap their "
          "push-out too (push_out_speed, default 2 m/s)."),
    Probe("long run", "reduced tumbler, 100 000 steps", x.long_run, j.long_run,
          "soft_step for long unattended runs.", quick_kw=dict(steps=5000)),
]


def run_probe(probe: Probe, solver: str, quick: bool = False, **kw) -> Outcome:
    """Measure and judge ``probe`` in ``solver`` (``kw`` to the measure); a crash is a failed
    outcome, not an exception; an unavailable mode is n/a."""
    if solver not in physics.solvers_available():
        return Outcome(UNAVAILABLE, "mode not available")
    t0 = time.perf_counter()
    try:
        out = probe.judge(probe.measure(solver, **(dict(probe.quick_kw) if quick else {}), **kw))
    except Exception as exc:  # a crash is an outcome too: report it, keep going
        out = Outcome(FAILED, f"crashed: {type(exc).__name__}: {exc}"[:160])
    out.seconds = time.perf_counter() - t0
    return out


@dataclass(frozen=True)
class ProbeCase:
    """One probe (its measure's function name) in one solver mode: plain data, so it runs the
    same on any Dask worker (bench/sweep.py)."""
    probe: str
    mode: str
    quick: bool = False

    @property
    def key(self) -> str:
        """``probe mode``: the case's name in a results file."""
        return f"{self.probe} {self.mode}"


def probe_task(case: ProbeCase) -> Outcome:
    """``run_probe`` of the case's probe and mode: the function the sweep sends to the workers."""
    probe = next(p for p in PROBES if p.measure.__name__ == case.probe)
    return run_probe(probe, case.mode, quick=case.quick)
