"""The per-step kernels that allocate nothing are compiled without numba's runtime (issue 13).

With the runtime on, every read of a table column (``F.body``, ``B.x``, ...) inside a loop is an
atomic reference-count pair.  Profiled on soft_step pyramid20 (400 pairs, 211 fixtures, the
shared 2-core VM): the fixture filter pass took 385 us a call with it and 3 us without, the
step's begin kernel 280 us against 90 us.  A speed check belongs in the benchmark
(``python -m bench --quick --modes soft_step --scenes pyramid20,rain1000 --refs pymunk --parts
speed``); this test keeps the flag from being dropped by accident, which no end-state test would
notice.  The second test shows the flag is not vacuous: a kernel so compiled refuses to
allocate, so the listed kernels really are allocation-free.
"""
from __future__ import annotations

import numpy as np
import pytest
from numba.core.errors import NumbaError

from physics._jit import kernel
from physics.collision.broadphase.fixture_filter import filter_pairs
from physics.collision.narrowphase.kernel import _rows
from physics.geometry.transform import update_geometry
from physics.step.checkpoint import count_nonfinite, restore_state, save_state
from physics.step.frame import begin_step, end_step

PER_STEP = [filter_pairs, begin_step, end_step, update_geometry, save_state, restore_state,
            count_nonfinite, _rows]


@pytest.mark.parametrize("fn", PER_STEP, ids=lambda f: f.py_func.__name__)
def test_per_step_kernel_runs_without_the_runtime(fn):
    assert fn.targetoptions.get("_nrt") is False


def test_a_kernel_without_the_runtime_cannot_allocate():
    @kernel(entry=True, cache=False)  # runtime-free: the default
    def allocates(n):
        return np.zeros(n).sum()

    with pytest.raises(NumbaError):
        allocates(3)
