"""app.panels.ticks.spaced_ticks: the stats plots' time axis labels keep 10 px apart, on the
finest 1-2-5 step that allows it (issue 16, item 9)."""
from __future__ import annotations

import math

import pytest

from app.panels.ticks import gaps_px, spaced_ticks, tick_labels

STEPS = {m * 10.0 ** e for m in (1, 2, 5) for e in range(-3, 5)}


def mono(label):
    """A 13 px font's digits are about 7 px wide; '-' and '.' narrower (like ImGui's default)."""
    return sum(4.0 if c in "-." else 7.0 for c in label)


def next_finer(step):
    m = round(step / 10.0 ** math.floor(math.log10(step) + 1e-9))
    e = math.floor(math.log10(step) + 1e-9)
    return {1: (5, e - 1), 2: (1, e), 5: (2, e)}[m]


CASES = [(-span, 0.0, w) for span in (0.3, 1.0, 2.0, 4.8, 10.0, 33.3, 120.0, 600.0, 3600.0)
         for w in (60.0, 120.0, 217.0, 400.0, 913.0, 1800.0)] + [(1.5, 7.25, 300.0), (-2.0, 3.0, 90.0)]


@pytest.mark.parametrize("t0,t1,width", CASES)
def test_gaps_step_and_finest(t0, t1, width):
    values, labels, step = spaced_ticks(t0, t1, width, mono)
    assert any(math.isclose(step, s, rel_tol=1e-9) for s in STEPS), step
    assert all(t0 - 1e-9 <= v <= t1 + 1e-9 for v in values)
    if len(values) >= 2:
        assert min(gaps_px(values, labels, t0, t1, width, mono)) >= 10.0
        assert values[1] - values[0] == pytest.approx(step)
    # the next finer 1-2-5 step crowds its labels (or this is the finest the search starts from)
    m, e = next_finer(step)
    finer_v, finer_l = tick_labels(t0, t1, m, e)
    if len(finer_v) >= 2:
        assert min(gaps_px(finer_v, finer_l, t0, t1, width, mono)) < 10.0, (step, m, e)


def test_known_answers():
    # 10 s over 400 px: 1 s ticks are 40 px apart, "-10" is 18 px, "-9" 11 px: gap 40-14.5 = 25.5;
    # 0.5 s ticks are 20 px apart, "-9.5" (22 px) next to "-9" (11 px): gap 3.5 < 10
    values, labels, step = spaced_ticks(-10.0, 0.0, 400.0, mono)
    assert step == 1.0 and labels[0] == "-10" and labels[-1] == "0" and len(values) == 11
    values, labels, step = spaced_ticks(-1.0, 0.0, 400.0, mono)
    assert step == pytest.approx(0.1) and labels[:2] == ["-1.0", "-0.9"] and labels[-1] == "0"
    # a narrow plot: the step grows to 5 s
    assert spaced_ticks(-30.0, 0.0, 120.0, mono)[2] == 10.0


def test_wide_labels_and_degenerate_ranges():
    wide = lambda s: 60.0    # noqa: E731 - every label 60 px: ticks >= 70 px apart
    values, labels, step = spaced_ticks(-10.0, 0.0, 350.0, wide)
    assert step == 2.0 and min(gaps_px(values, labels, -10.0, 0.0, 350.0, wide)) >= 10
    assert spaced_ticks(0.0, 0.0, 300.0, mono) == ([], [], 0.0)
    assert spaced_ticks(0.0, 1.0, 0.0, mono) == ([], [], 0.0)
    assert spaced_ticks(float("nan"), 1.0, 100.0, mono) == ([], [], 0.0)
    # tinier than a label: at most one tick, never an endless search
    assert len(spaced_ticks(-1.0, 0.0, 5.0, wide)[0]) <= 1
