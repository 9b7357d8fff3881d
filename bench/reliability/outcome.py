"""A probe's outcome: held, degraded, failed (or n/a), with its figure as text."""
from __future__ import annotations

from dataclasses import dataclass, field

HELD, DEGRADED, FAILED, UNAVAILABLE = "held", "degraded", "failed", "n/a"


@dataclass
class Outcome:
    """``status`` (HELD, DEGRADED, FAILED, UNAVAILABLE), ``figure`` (the table's text),
    ``metrics`` (the scenario's figures), ``seconds`` (wall time of the probe)."""
    status: str
    figure: str
    metrics: dict = field(default_factory=dict)
    seconds: float = 0.0

    def __str__(self):
        return f"{self.status}: {self.figure}"


def refusal(m: dict, status=FAILED) -> Outcome:
    """The outcome of a run that ended in a SimulationError (figures from ``refused``)."""
    return Outcome(status, f"SimulationError at step {m['error_step']} ({m['stage']}: {', '.join(m['bodies'][:3])})",
                   m)


def graded(worst: float, held: float, degraded: float, fig: str, m: dict) -> Outcome:
    """HELD below ``held``, DEGRADED below ``degraded``, else FAILED."""
    return Outcome(HELD if worst < held else DEGRADED if worst < degraded else FAILED, fig, m)
