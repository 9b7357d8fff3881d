"""Restitution at first touch (issue 18): a 1 x 1 box with e = 0.5 dropped from 0.2 to 5 m,
flat and on a corner, rises to within 5 % of the ideal e^2 h.

Box2D v3 reaches 0.67..0.98 of the ideal (``restitution.flat.h0.2`` = 0.0335 of 0.05 m ...
``restitution.corner.h5`` = 1.223 of 1.25 m in bench/results/box2d_v3_figures.json): it
reflects the normal speed the step began with, once, after the last sub-step.  The bound here
is the issue's (5 %), which is also above every Box2D figure.
"""
import pytest

from bench.box2d.figures_cases import fig_restitution
from bench.suite import measures as M
from bench.reliability.samples import run_ours

from accuracy_common import box2d

HEIGHTS = (0.2, 0.5, 1.0, 2.0, 5.0)


@pytest.mark.parametrize("corner", [False, True], ids=["flat", "corner"])
@pytest.mark.parametrize("height", HEIGHTS)
def test_bounce_apex_within_5_percent(height, corner):
    tr, desc, sim = run_ours("restitution_drop", 4.0, scene_kw={"height": height, "corner": corner})
    apex = M.bounce_apex(tr, tr.i("box"), 2 ** -0.5 if corner else 0.5)
    ideal = 0.25 * height
    key = f"restitution.{'corner' if corner else 'flat'}.h{height:g}"
    print(f"{key}: ours {apex:.4f} m, Box2D v3 {box2d(key):.4f} m, ideal {ideal:.4f} m")
    assert abs(apex / ideal - 1) < 0.05
    assert abs(apex - ideal) <= abs(box2d(key) - ideal)


def test_worst_ratio_of_the_sweep():
    """The sweep's figure as docs/reliability.md shows it (``restitution.worst_ratio``: Box2D 0.669)."""
    figs = {f.id: f.value for f in fig_restitution(run_ours)}
    assert figs["restitution.worst_ratio"] > 0.95 > box2d("restitution.worst_ratio")


def test_elastic_bounce_gains_no_energy():
    """e = 1 dropped flat: the bounce apex is at most the drop height (restitution never adds energy)."""
    tr, desc, sim = run_ours("restitution_drop", 4.0, scene_kw={"height": 1.0, "e": 1.0})
    apex = M.bounce_apex(tr, tr.i("box"), 0.5)
    assert 0.95 < apex <= 1.0 + 1e-6
