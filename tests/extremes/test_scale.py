"""Extremes: scale and float precision (issue 9)."""
import pytest

from bench.scenarios.extremes import far_pyramid, large_stack, small_stack, ten_thousand
from extremes_common import CONTINUOUS


@pytest.mark.parametrize("solver", CONTINUOUS)
def test_100m_boxes_stack(solver):
    """Regime: five 100 m boxes stacked on ground, 4 s.

    Outcome: the top box sinks and drifts less than 10% of a box size, all finite."""
    m = large_stack(solver)
    assert m["finite"] and m["sink"] < 0.1 and m["drift"] < 0.1


def test_1cm_boxes_stack_default_soft_step():
    """Regime: five 0.01 m boxes stacked, default soft_step (its contact stiffness does not scale
    with size), 4 s.

    Outcome: finite, still a stack: the top box has sunk less than 75% of a box (measured ~55%:
    each contact overlaps ~1.4 mm) and drifted sideways less than 10%."""
    m = small_stack("soft_step")
    assert m["finite"] and m["sink"] < 0.75 and m["drift"] < 0.1


def test_1cm_boxes_stack_tuned_soft_step():
    """Regime: the same 1 cm stack with 16 sub-steps and 120 Hz contacts (the advice).

    Outcome: sink and drift below 10% of a box size."""
    m = small_stack("soft_step", settings=dict(substeps=16, contact_hertz=120.0))
    assert m["finite"] and m["sink"] < 0.1 and m["drift"] < 0.1


@pytest.mark.parametrize("solver", CONTINUOUS)
def test_pyramid_10km_from_origin_matches_pyramid_at_origin(solver):
    """Regime: a 55-box pyramid at (6000, 8000) m and one at the origin, 300 steps each.

    Outcome: relative positions agree within 1 cm and the far pyramid drifts less than 5 cm."""
    m = far_pyramid(solver)
    assert m["finite"] and m["difference"] < 0.01 and m["drift_far"] < 0.05


@pytest.mark.slow
def test_ten_thousand_bodies():
    """Regime: 10 000 boxes (0.4 m) dropped in a 200 x 50 grid onto ground, 60 steps, soft_step.

    Outcome: all finite, none below the ground surface, total energy not above its start,
    and under 1 s per step."""
    m = ten_thousand("soft_step", steps=60)
    assert m["finite"] and m["below"] == 0
    assert m["energy_rise"] <= 1e-6 * abs(m["e0"])
    assert m["ms_per_step"] < 1000
