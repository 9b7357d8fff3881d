"""Extremes: degenerate geometry (issue 9)."""
import numpy as np
import pytest

import physics
from bench.scenarios.extremes import coincident, near_collinear, slivers, was_refused
from extremes_common import CONTINUOUS, MODES


@pytest.mark.parametrize("solver", CONTINUOUS)
def test_near_collinear_vertices_rest(solver):
    """Regime: boxes with an extra vertex 1e-7 m off the middle of two edges, stacked three high.

    Outcome: at rest (< 0.05 m/s) after 8 s, the stack upright, sink below 2 cm, finite."""
    m = near_collinear(solver)
    assert m["finite"] and m["upright"] and m["sink"] < 0.02 and m["speed"] < 0.05


@pytest.mark.parametrize("solver", CONTINUOUS)
def test_slivers_1_to_1000(solver):
    """Regime: 1 m x 1 mm slivers dropped flat, tilted, end-first at 10 m/s, and stacked.

    Outcome: no point ever goes more than 5 mm below the ground surface (no tunnelling), energy
    never rises above the start by more than 1 mJ, all at rest after 5 s."""
    m = slivers(solver)
    assert m["finite"]
    assert m["deepest"] > -0.005
    assert m["energy_rise"] <= 1e-3
    assert m["speed"] < 0.05


def test_coincident_bodies_separate_gently_soft_step():
    """Regime: eight 1 m boxes created at exactly the same place, no gravity, soft_step.

    Outcome: no body ever exceeds 3x the push-out cap (push_out_speed 3 m/s: pushes from several
    overlapping neighbours add up; measured 6.1 m/s), the overlap left
    after 5 s is below 2 cm, momentum stays zero (1e-9 kg m/s)."""
    m = coincident("soft_step")
    assert m["finite"]
    assert m["max_speed"] <= 3 * 3.0
    assert m["depth"] < 0.02
    assert m["momentum"] < 1e-9


@pytest.mark.parametrize("solver", MODES)
def test_coincident_bodies_never_explode(solver):
    """Regime: the same eight coincident boxes in every mode.

    Outcome: finite, no body faster than 10 m/s (capped push-out), momentum stays zero."""
    m = coincident(solver)
    assert not was_refused(m), m
    assert m["finite"] and m["max_speed"] <= 10.0 and m["momentum"] < 1e-6


def test_degenerate_polygons_are_refused_with_a_reason():
    """Regime: polygons at the edge of validity.  Outcome: collinear/zero-area/repeated input is a
    ValueError naming the problem; the 1e-7 near-collinear and 1:1000 shapes are accepted."""
    for pts, word in (([(0, 0), (1, 0), (2, 0)], "zero area"), ([(0, 0), (1, 0), (1, 0), (0, 1)], "repeated"),
                      ([(0, 0), (1, 0), (2, 1e-13), (0, 1)], "collinear")):
        with pytest.raises(ValueError, match=word):
            physics.Polygon(pts)
    assert physics.Polygon([(0, 0), (1, -1e-7), (2, 0), (2, 1), (0, 1)]).area > 0
    assert np.isclose(physics.Polygon.box(1.0, 0.001).area, 0.001)
