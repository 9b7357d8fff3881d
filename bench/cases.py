"""Benchmark cases: plain data that says everything one run needs, and nothing live.

A case carries its scene (the raw description and the world fields the benchmark overrides,
``bench.scenes.SceneData``), its solver configuration (``bench.configs.Config``) and its plan,
so it can be pickled or turned into JSON (``asdict``) and run the same in any process: the
physics is deterministic, so the figures (not the timings) are bit-identical wherever it runs.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from .configs import Config
from .scenes import SceneData


@dataclass(frozen=True)
class Plan:
    """How long a timed run is: ``steps`` in all, timed in chunks of ``chunk`` steps, the first
    ``warm`` steps untimed."""
    steps: int
    chunk: int
    warm: int


@dataclass(frozen=True)
class SpeedCase:
    """One configuration of Stelkropp on one scene, interleaved with ``engines`` (reference engine
    names) on fresh copies of the same scene.  ``budget_s``: seconds before the run is cut;
    ``width``: container width (m) for the escaped count; ``ref_metrics``: also measure the
    references' figures at the end (one case per scene is enough)."""
    scene: SceneData
    config: Config
    plan: Plan
    engines: tuple = ()
    budget_s: float | None = None
    width: float | None = None
    ref_metrics: bool = False


@dataclass(frozen=True)
class ScalingCase:
    """``n`` boxes in columns of 10 (bench.scenes.columns) in ``mode``, interleaved with ``engines``."""
    n: int
    mode: str
    engines: tuple = ()


@dataclass(frozen=True)
class AccuracyCase:
    """The accuracy scenarios ``names`` (bench.accuracy.SCENARIOS) in one engine at time step
    ``dt`` (s): Stelkropp with ``config`` (and ``integrator``, None: the mode's own), or a
    reference ``engine`` with ``config`` None."""
    engine: str
    config: Config | None
    dt: float
    integrator: str | None
    names: tuple


def asdict(case) -> dict:
    """The case as nested plain dicts (JSON-ready)."""
    return dataclasses.asdict(case)
