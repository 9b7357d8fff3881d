"""Shared pieces of the accuracy tests (issue 18): Box2D v3's figures and our runs of its samples.

``box2d(key)`` is a value of ``bench/results/box2d_v3_figures.json`` (measured by ``python -m
bench.box2d.samples`` on the same descriptions); ``ours(figure_function)`` measures the same
figures in Stelkropp's default mode (soft_step defaults, dt 1/60, 4 sub-steps, sleeping off)
through ``bench.reliability.samples.run_ours``, so a test and docs/reliability.md measure the same
thing.
"""
import json
from pathlib import Path

from bench.reliability.samples import run_ours

FIGURES = Path(__file__).resolve().parents[2] / "bench" / "results" / "box2d_v3_figures.json"
_B2 = {f["id"]: f["value"] for f in json.loads(FIGURES.read_text())["figures"]}


def box2d(key):
    """Box2D v3's value of figure ``key`` (KeyError names an unknown key)."""
    return _B2[key]


def ours(figure_function, **kw):
    """{figure id: value} of one ``bench/box2d/figures_*.py`` function run in Stelkropp."""
    return {f.id: f.value for f in figure_function(lambda *a, **k: run_ours(*a, **k), **kw)}
