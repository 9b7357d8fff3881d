"""Kernels only compiled code calls have no Python wrapper (physics/_jit.py ``entry``): calling one
from Python raises RuntimeError naming it, instead of jumping to a wrapper that is not there; an
entry and its internal callees work from Python as before."""
import numpy as np
import pytest

from physics._jit import kernel


@kernel(cache=False)
def _twice(x):
    return 2.0 * x


@kernel(cache=False, entry=True)
def _sum_twice(a):
    s = 0.0
    for v in a:
        s += _twice(v)
    return s


def test_an_entry_calls_its_internal_callee():
    assert _sum_twice(np.arange(4.0)) == 12.0


def test_an_internal_kernel_called_from_python_raises_naming_it():
    with pytest.raises(RuntimeError, match="_twice is a kernel only compiled code calls"):
        _twice(1.0)


def test_the_core_step_entries_have_wrappers_and_helpers_do_not():
    from physics.constraints.contact_soft import prepare_contacts
    from physics.step.one_call import soft_world_step
    assert not soft_world_step.targetoptions.get("no_cpython_wrapper", False)
    assert prepare_contacts.targetoptions.get("no_cpython_wrapper") is True
