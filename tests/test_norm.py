"""geometry/norm.length: math.hypot's value to within one rounding, at any magnitude."""
import math

import numpy as np
from numba import njit

from physics.geometry.norm import length


@njit
def _lengths(xs, ys, out):
    for i in range(xs.shape[0]):
        out[i] = length(xs[i], ys[i])


def _run(xs, ys):
    out = np.empty(len(xs))
    _lengths(np.asarray(xs, float), np.asarray(ys, float), out)
    return out


def test_length_is_hypot_within_one_rounding():
    rng = np.random.default_rng(7)
    # magnitudes from 1e-200 to 1e200: both the sqrt path and the hypot fallback
    mag = 10.0 ** rng.uniform(-200, 200, 20000)
    xs = mag * rng.standard_normal(20000)
    ys = mag * rng.standard_normal(20000) * 10.0 ** rng.uniform(-8, 8, 20000)
    got = _run(xs, ys)
    want = np.array([math.hypot(x, y) for x, y in zip(xs, ys)])
    assert np.all(np.abs(got - want) <= np.spacing(want)), "more than one rounding from hypot"


def test_length_edges():
    got = _run([0.0, -0.0, 3.0, 1e200, 1e-300, math.inf, math.nan, -4.0],
               [0.0, 0.0, 4.0, 1e200, 1e-300, 1.0, 1.0, 3.0])
    assert got[0] == 0.0 and got[1] == 0.0 and got[2] == 5.0 and got[7] == 5.0
    assert got[3] == math.hypot(1e200, 1e200)  # would overflow as a sum of squares
    assert got[4] == math.hypot(1e-300, 1e-300)  # would underflow to 0
    assert got[5] == math.inf and math.isnan(got[6])
