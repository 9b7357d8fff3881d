"""The extreme scenarios are pinned: the reliability table (bench/reliability) and these tests
run the same scenarios (bench/scenarios/extremes), so a change to one is a change to both and
must be made on purpose (tests/extreme_pins.py)."""
import pytest

from bench.scenarios.extremes import PINNED
from extreme_pins import describe, digest, load_record


def test_every_scenario_is_pinned():
    """Regime: the scenario list.  Outcome: the record pins exactly the scenarios there are."""
    assert sorted(load_record()) == sorted(PINNED)


# building the 10 000-body world takes ~10 s: it joins the slow tier with the scenario itself
@pytest.mark.parametrize("name", [pytest.param(n, marks=[pytest.mark.slow] if n == "ten_thousand" else [])
                                  for n in sorted(PINNED)])
def test_scenario_is_unchanged(name):
    """Regime: each scenario's initial world (built in soft_step) and its run lengths.

    Outcome: the digest equals the pinned one; if the change was deliberate, re-pin with
    `python -m tests.extreme_pins` in the same commit and say why."""
    assert digest(name) == load_record()[name], \
        f"scenario {name} changed: if deliberate, re-pin (python -m tests.extreme_pins)"


def test_pin_sees_a_one_ulp_change():
    """Regime: the description the digest hashes.  Outcome: moving one body by one ulp changes it
    (the pin is exact, not rounded)."""
    import math
    build, kwargs, _ = PINNED["mass_ratio_stack"]
    w, parts = build("soft_step", **kwargs)
    before = describe(w)
    x, y = parts["heavy"].position
    parts["heavy"].position = (x, math.nextafter(y, 2.0))
    assert describe(w) != before
