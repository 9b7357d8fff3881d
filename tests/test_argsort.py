"""The kernels' merge argsort (physics/collision/argsort.py) gives numpy's stable order: ties in
index order and NaN keys last, for floats and integers, every length from empty up."""
import numpy as np
import pytest

from physics._jit import kernel
from physics.collision.argsort import argsort_into


@kernel(entry=True)
def _sorted(key, n, order, tmp):
    argsort_into(key, n, order, tmp)


def _order(key):
    n = len(key)
    order = np.full(n + 3, -7, np.int64)   # longer than n: nothing past n is touched
    _sorted(key, n, order, np.zeros(n + 3, np.int64))
    assert np.all(order[n:] == -7)
    return order[:n]


@pytest.mark.parametrize("seed", range(4))
def test_merge_argsort_is_numpys_stable_order(seed):
    rng = np.random.default_rng(seed)
    for n in list(range(70)) + [255, 256, 257, 1000]:
        ties = rng.integers(0, max(n // 4, 1), n).astype(np.float64)
        spread = rng.normal(size=n)
        if n:
            spread[rng.integers(0, n, 1 + n // 10)] = np.nan
        ints = rng.permutation(4 * n + 1)[:n].astype(np.int64)
        for key in (ties, spread, ints, ties[::-1].copy()):
            assert np.array_equal(_order(key), np.argsort(key, kind="stable")), (n, key)
