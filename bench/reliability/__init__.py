"""Reliability at the extremes: every probe in every solver mode -> docs/reliability.md.

    python -m bench.reliability [--quick] [--modes soft_step,sequential_impulse] [--probes NAMES] [--out PATH]

Each probe runs one extreme scenario (bench/scenarios/extremes: mass ratio, stiff spring,
speed, scale, degenerate geometry, long run) in one solver mode with that mode's default
settings and judges its figures (judges.py).  The outcome is

- **held**: the claim of the regime holds (finite, bounded energy, no tunnelling, drift below
  the stated bound);
- **degraded**: the world stayed finite and honest but the claim holds only approximately
  (e.g. sinks or drifts beyond the bound but less than a body size), or the step was refused
  with a clear ``SimulationError`` where that is an acceptable answer (stiff springs in an
  explicit mode);
- **failed**: tunnelling, energy growth, non-finite values, an unexplained
  ``SimulationError``, or a claim missed by more than a body size.

The tests in ``tests/extremes/`` run the same scenarios and assert their own bounds on the
same figures, so the table and the suite measure the same thing.
"""
from .outcome import DEGRADED, FAILED, HELD, UNAVAILABLE, Outcome
from .probes import PROBES, Probe, run_probe

__all__ = ["DEGRADED", "FAILED", "HELD", "UNAVAILABLE", "Outcome", "PROBES", "Probe", "run_probe"]
