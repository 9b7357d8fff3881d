"""The flat arrays a step entry point takes rebuild, inside compiled code, the very views the
store hands kernels from Python (physics/store/flat.py): the same numba types (so every kernel
behind an entry point compiles once, whichever side calls it) and the same memory."""
import numba
import numpy as np
import pytest

from physics.store import Store
from physics.store import flat
from physics.store.make_flat import main as make_flat


def tables():
    s = Store()
    for t in (s.bodies, s.fixtures, s.springs, s.joints):
        t.add()
    s.verts.add(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]))
    return {"bodies": s.bodies.arrays, "fixtures": s.fixtures.arrays, "verts": s.verts.arrays,
            "springs": s.springs.arrays, "joints": s.joints.arrays,
            "contacts": _contacts(s)}


def _contacts(s):
    from physics.store.contacts import CONTACT_FIELDS
    from physics.store.table import allocate
    return allocate(CONTACT_FIELDS, 8)


@pytest.mark.parametrize("name", ["bodies", "fixtures", "verts", "springs", "joints", "contacts"])
def test_a_flat_view_is_the_python_view(name):
    cols = tables()[name]
    fn = getattr(flat, f"{name}_view")
    got = fn(*cols.flat)
    want = [cols[f[0]] for f in cols.spec]
    assert fn.nopython_signatures[-1].return_type.types == tuple(numba.typeof(a) for a in want)
    for g, w in zip(got, want):
        assert g.shape == w.shape and g.dtype == w.dtype and np.shares_memory(g, w)
        w[...] = np.arange(w.size).reshape(w.shape).astype(w.dtype)  # written through one,
        assert np.array_equal(g, w)                                   # read through the other


def test_flat_py_is_generated_from_the_table_specs(capsys):
    assert make_flat(["--check"]) == 0, capsys.readouterr().out
