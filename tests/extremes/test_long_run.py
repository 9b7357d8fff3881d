"""Extremes: long run (issue 9)."""
import pytest

from bench.scenarios.extremes import long_run


@pytest.mark.slow
def test_tumbler_100k_steps_energy_bounded():
    """Regime: 100 000 steps (27.8 simulated minutes) of a reduced tumbler: a 12-sided drum
    (r 3 m, 0.5 rad/s) of kinematic walls with 24 boxes, discs and pentagons inside, soft_step.
    Cost: ~50-60 s on one core (0.5-0.6 ms per step, measured by bench.reliability).

    Outcome: all finite, no body leaves the drum, and the largest total energy of the contents in
    the last tenth of the run is at most 1.5x that of the first tenth (no secular growth)."""
    m = long_run("soft_step")
    assert m["finite"] and m["escaped"] == 0
    assert m["ratio"] <= 1.5
