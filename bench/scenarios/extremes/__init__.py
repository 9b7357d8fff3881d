"""The extreme scenarios: one definition that ``python -m bench.reliability`` (the table in
docs/reliability.md) and ``tests/extremes/`` (the assertions) both run.

Each scenario is a builder (``build_*``: the initial world and its named bodies) and a measure
(the scenario's name: builds, runs, returns its figures as a dict; a refused step returns the
``refused`` figures: ``error``, ``error_step``, ``stage``, ``bodies``).  Neither side judges
here: the reliability probes turn figures into held/degraded/failed, the tests assert their
own bounds.  ``PINNED`` lists every initial world with the run lengths, so that
tests/extremes/test_pinned_scenarios.py notices any change to what is measured.
"""
from __future__ import annotations

import inspect

from .common import refused, run_steps, total_energy
from .geometry import (NEAR_COLLINEAR, build_coincident, build_near_collinear, build_slivers, coincident,
                       near_collinear, slivers)
from .loads import (CHAIN_C, CHAIN_K, CHAIN_LINKS, CHAIN_REST, STIFF_K, build_mass_ratio_stack,
                    build_spring_chain, build_stiff_spring, mass_ratio_stack, spring_chain, stiff_spring)
from .long_run import TUMBLER_R, TUMBLER_W, Drum, build_tumbler, long_run
from .scale import (FAR, build_far_pyramid, build_scaled_stack, build_ten_thousand, far_pyramid, large_stack,
                    scaled_stack, small_stack, ten_thousand)
from .speed import WALL_T, WALL_X, build_bullets, bullets, volley

# name -> (builder, builder keyword arguments, the measure whose defaults are pinned beside it)
PINNED = {
    "mass_ratio_stack": (build_mass_ratio_stack, {}, mass_ratio_stack),
    "spring_chain": (build_spring_chain, {}, spring_chain),
    "stiff_spring": (build_stiff_spring, {}, stiff_spring),
    "bullets": (build_bullets, {}, bullets),
    "volley": (build_bullets, {"spacing": 3.0}, volley),
    "small_stack": (build_scaled_stack, {"size": 0.01}, scaled_stack),
    "large_stack": (build_scaled_stack, {"size": 100.0}, scaled_stack),
    "far_pyramid@origin": (build_far_pyramid, {}, far_pyramid),
    "far_pyramid@far": (build_far_pyramid, {"origin": FAR}, far_pyramid),
    "ten_thousand": (build_ten_thousand, {}, ten_thousand),
    "near_collinear": (build_near_collinear, {}, near_collinear),
    "slivers": (build_slivers, {}, slivers),
    "coincident": (build_coincident, {}, coincident),
    "long_run": (build_tumbler, {}, long_run),
}


def defaults(measure) -> dict:
    """The keyword defaults of a measure (run lengths, counts): part of what a scenario is."""
    return {k: p.default for k, p in inspect.signature(measure).parameters.items()
            if p.default is not inspect.Parameter.empty}


def was_refused(figures: dict) -> bool:
    """Whether a measure's figures are those of a refused step (``refused``)."""
    return "error_step" in figures


__all__ = [
    "PINNED", "defaults", "was_refused", "refused", "run_steps", "total_energy",
    "mass_ratio_stack", "spring_chain", "stiff_spring", "bullets", "volley", "scaled_stack", "small_stack",
    "large_stack", "far_pyramid", "ten_thousand", "near_collinear", "slivers", "coincident", "long_run",
    "build_mass_ratio_stack", "build_spring_chain", "build_stiff_spring", "build_bullets", "build_scaled_stack",
    "build_far_pyramid", "build_ten_thousand", "build_near_collinear", "build_slivers", "build_coincident",
    "build_tumbler", "Drum", "NEAR_COLLINEAR", "CHAIN_C", "CHAIN_K", "CHAIN_LINKS", "CHAIN_REST", "STIFF_K",
    "TUMBLER_R", "TUMBLER_W", "FAR", "WALL_T", "WALL_X",
]
