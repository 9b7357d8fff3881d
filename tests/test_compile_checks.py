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

    with pytest.raises(RuntimeError, match="echo"), returns_checked():
        echo(np.zeros(3))


def test_a_runtime_free_kernel_returning_a_tuple_with_an_array_is_named():
    @numba.njit(_nrt=False)
    def pair(a, n):
        return n, a

    with pytest.raises(RuntimeError, match="pair"), returns_checked():
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


def test_a_kernel_compiled_for_a_literal_argument_is_named():
    """A constant passed to a kernel compiles it once per constant (numba types it as a literal):
    the precompile names such calls; plain values pass."""
    from physics.compile_checks import literals_checked

    @numba.njit
    def pick(a, flag):
        return a[0] if flag else a[1]

    @numba.njit
    def both(a):
        return pick(a, True) + pick(a, False)

    @numba.njit
    def plain(a):
        return pick(a, np.bool_(True)) + pick(a, np.bool_(False))

    with pytest.raises(RuntimeError, match=r"pick \(argument 1: Literal\[bool\]\(True\)\)"):
        with literals_checked():
            both(np.arange(2.0))
    with literals_checked() as check:
        assert plain(np.arange(2.0)) == 1.0
    assert check.bad == []
