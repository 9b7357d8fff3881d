"""The one-call step's broad phase drops the pairs whose bodies cannot meet within the step
(physics/collision/reach.py) before sorting them; the narrow phase dropped exactly those itself.
So the simulation is bit for bit what the Python path computes, which hands every overlapping
pair to the narrow phase."""
import numpy as np

from builders import ground, world
import physics


def _shower(w, seed=3):
    """Fast boxes thrown across and into each other above a ground: fat boxes (speeds up to
    40 m/s, 0.67 m a step) that overlap many boxes they cannot reach."""
    ground(w)
    rng = np.random.default_rng(seed)
    for _ in range(160):
        x, y = rng.uniform(-8, 8), rng.uniform(0.5, 12)
        v = rng.uniform(-40, 40, 2)
        w.add_body(physics.Polygon.box(0.4, 0.4), position=(x, y), velocity=tuple(v),
                   angular_velocity=float(rng.uniform(-20, 20)))


def test_the_reach_filter_changes_the_pair_count_and_nothing_else():
    fast, python = world(), world()
    for w in (fast, python):
        _shower(w)
    python.pair_filter = lambda fa, fb: True  # a pair filter runs the step's Python path
    fewer = 0
    for _ in range(90):
        fast.step()
        python.step()
        a, b = fast.state(), python.state()
        assert all(np.array_equal(a[k], b[k]) for k in ("position", "angle", "velocity", "angular_velocity"))
        assert fast._pipeline.npairs <= python._pipeline.npairs
        fewer += fast._pipeline.npairs < python._pipeline.npairs
    assert fast._pipeline.python_steps == 0 and python._pipeline.python_steps == 90
    assert fewer > 30  # the filter did drop pairs, on most steps
