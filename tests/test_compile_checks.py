"""The precompile's check that no runtime-free kernel returns an array (physics/compile_checks.py):
it names one that does, passes one that returns a number, and the core's kernels pass it (every
unit of a cold precompile runs under it: compile_units._worker)."""
import numba
import numpy as np
import pytest

from physics.compile_checks import holds_array, returns_checked


def test_a_runtime_free_kernel_returning_its_argument_is_named():
    @numba.njit(_nrt=False)
    def echo(a):
        return a

    with pytest.raises(RuntimeError, match="echo"):
        with returns_checked():
            echo(np.zeros(3))


def test_a_runtime_free_kernel_returning_a_tuple_with_an_array_is_named():
    @numba.njit(_nrt=False)
    def pair(a, n):
        return n, a

    with pytest.raises(RuntimeError, match="pair"):
        with returns_checked():
            pair(np.zeros(3), 2)


def test_numbers_and_runtime_kernels_pass():
    @numba.njit(_nrt=False)
    def total(a):
        return a.sum()

    @numba.njit(_nrt=True)
    def fresh(n):
        return np.zeros(n)

    with returns_checked() as check:
        assert total(np.ones(4)) == 4.0
        assert fresh(2).shape == (2,)
    assert check.bad == []


def test_holds_array_sees_into_tuples():
    arr = numba.types.float64[:]
    assert holds_array(numba.types.Tuple((numba.types.int64, numba.types.UniTuple(arr, 2))))
    assert not holds_array(numba.types.UniTuple(numba.types.float64, 3))


def test_a_runtime_free_kernel_taking_arrays_from_a_runtime_kernel_is_named():
    @numba.njit(_nrt=True)
    def grown(a, n):
        return np.zeros(n) if n > a.shape[0] else a

    @numba.njit(_nrt=False)
    def user(a, n):
        b = grown(a, n)
        return b.shape[0]

    with pytest.raises(RuntimeError, match="user takes arrays from .*grown"):
        with returns_checked():
            user(np.zeros(3), 5)
