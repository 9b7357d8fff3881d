"""Box2D v3's HighMassRatio1 (three pyramids of 2 m boxes, each top box 100, 200 and 300 times
denser and dropped 2 m onto its pyramid) in the default mode.

Issue 41 asks that it move less than 0.1 m.  The sample's first figure is the top box's whole
displacement, which holds its 2 m fall (2.08 m here, Box2D v3 2.21 m), so the bound applies to
``rest_displacement_10s``: every box's distance at 10 s from where it rests (a top box 2 m below
its start).  Bounds: the issue's 0.1 m and Box2D v3's own figure on the same description
(bench/results/box2d_v3_figures.json: 0.76 m).  Measured here: 0.096 m (the 300x box, which
sinks 8 cm into its pyramid and slides 5 cm), the other boxes 0.093 m at most.
"""
from bench.box2d.figures_samples import fig_high_mass_ratio

from accuracy_common import box2d, ours


def test_the_pyramids_hold_their_heavy_tops_within_ten_centimetres():
    figures = ours(fig_high_mass_ratio)
    rest = figures["high_mass_ratio_1.rest_displacement_10s"]
    print(f"HighMassRatio1: ours {rest:.4g} m from rest, Box2D v3 {box2d('high_mass_ratio_1.rest_displacement_10s'):.4g}")
    assert rest < 0.1 and rest <= box2d("high_mass_ratio_1.rest_displacement_10s")
    # the fall itself: the top boxes land (about 2 m moved) and are not thrown further than Box2D's
    top = figures["high_mass_ratio_1.top_displacement_10s_max"]
    assert 1.9 < top <= 1.05 * box2d("high_mass_ratio_1.top_displacement_10s_max")
