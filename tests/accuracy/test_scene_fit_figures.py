"""Thin, small and heavy-over-light bodies in the default mode: soft_step chooses eight sub-steps
for them (physics/solvers/soft_step/fit.py) and so holds Box2D v3's Card House, Tiny Pyramid and
HighMassRatio2, which four sub-steps do not (docs/reliability.md).

Bounds: Box2D v3's figures at its own 4 sub-steps on the same descriptions
(bench/results/box2d_v3_figures.json: the top card moves 0.035 m in 10 s, the top box 1.33 box
sizes, the big box sinks 0.086 m), with 5 % slack as docs/reliability.md judges.  Measured here:
0.026 m, 1.01 box sizes and 0.018 m at eight sub-steps; 1.9 m, 20.4 box sizes and 0.49 m at four.  The scenes are built without a sub-step
count, so the count is the world's own choice, and the test checks it chose eight.
"""
import pytest
from bench.box2d.figures_cases import fig_mass_ratio
from bench.box2d.figures_samples import fig_card_house, fig_high_mass_ratio, fig_tiny_pyramid
from bench.reliability.samples import run_ours

from accuracy_common import box2d


def _default_mode(figure_function):
    """({figure id: value}, [the worlds run]) in the default mode: no sub-step count given."""
    worlds = []

    def run(name, seconds, substeps=None, scene_kw=None):
        out = run_ours(name, seconds, None, scene_kw)
        worlds.append(out[2].world)
        return out
    return {f.id: f.value for f in figure_function(run)}, worlds


@pytest.mark.parametrize("figure_function, key", [
    (fig_card_house, "card_house.max_card_displacement_10s"),
    (fig_tiny_pyramid, "tiny_pyramid.top_displacement_10s"),
    (fig_high_mass_ratio, "high_mass_ratio_2.big_sink_10s"),
], ids=["card_house", "tiny_pyramid", "high_mass_ratio_2"])
def test_the_default_mode_holds_what_box2d_holds(figure_function, key):
    figures, worlds = _default_mode(figure_function)
    assert worlds and all(w.settings["substeps"] == 8 and w.settings.chosen() for w in worlds)
    ours = figures[key]
    print(f"{key}: ours in the default mode {ours:.4g}, Box2D v3 at 4 sub-steps {box2d(key):.4g}")
    assert ours <= 1.05 * box2d(key)


def test_a_1000_to_1_stack_stands_in_the_default_mode():
    """Issue 18's 1000 kg box on a 1 kg box (bench/suite/cases.py mass_ratio_1000).  Box2D v3 does
    not hold it (bench/results/box2d_v3_figures.json: toppled, sink 1.0 m), so the bound is the
    issue's own: below 5 cm and standing.  The world chooses the stiffest soft contacts for it
    (fit.py); measured here 3.5 cm, and 8.6 cm with the default contacts at any sub-step count."""
    figures, worlds = _default_mode(fig_mass_ratio)
    assert box2d("mass_ratio_1000.toppled_10s") and box2d("mass_ratio_1000.sink_4_5s") > 0.05
    assert worlds and all(w.settings.chosen()["contact_hertz"][0] > w.settings.declared()["contact_hertz"].default
                          for w in worlds)
    sink = figures["mass_ratio_1000.sink_4_5s"]
    print(f"1000:1 stack: sink {sink:.4g} m in the default mode")
    assert sink < 0.05 and not figures["mass_ratio_1000.toppled_10s"]
