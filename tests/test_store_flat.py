"""The flat arrays a step entry point takes rebuild, inside compiled code, the very views the
store hands kernels from Python (physics/store/flat.py): the same numba types (so every kernel
behind an entry point compiles once, whichever side calls it) and the same memory."""
import numba
import numpy as np
import pytest

from physics.store import Store, flat
from physics.store.bodies import Bodies
from physics.store.contacts import Contacts
from physics.store.fixtures import Fixtures
from physics.store.joints import Joints
from physics.store.make_flat import main as make_flat
from physics.store.springs import Springs
from physics.store.vertices import Verts


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
    """The view compiled code builds from the flat arrays has the numba type of the Python view
    over the same arrays, and each of its fields is that view's column (same memory)."""
    cols = tables()[name]
    py = {"bodies": Bodies, "fixtures": Fixtures, "verts": Verts, "springs": Springs, "joints": Joints,
          "contacts": Contacts}[name](**cols)
    fn = getattr(flat, f"{name}_view")
    fn(*cols.flat)
    assert fn.nopython_signatures[-1].return_type == numba.typeof(py)
    assert len(py._sources) <= 2 + len(cols.X)  # the flat arrays, not one array per field

    for f in cols.spec:
        k = f[0]
        w = getattr(py, k)
        w[...] = np.arange(w.size).reshape(w.shape).astype(w.dtype)  # written through Python,
        for g in (_field(k)(py), _field(k, fn)(*cols.flat)):          # read in compiled code
            assert g.shape == w.shape and g.dtype == w.dtype and np.shares_memory(g, w)
            assert np.array_equal(g, w)


def _field(k, view=None):
    """A compiled function returning field ``k`` of the table it is given, or of the one ``view``
    builds from the flat arrays (one function per field: an attribute name is a constant)."""
    from numba import njit
    src = f"lambda T: T.{k}" if view is None else f"lambda *a: view(*a).{k}"
    return njit(eval(src, {"view": view}))


def test_flat_py_is_generated_from_the_table_specs(capsys):
    assert make_flat(["--check"]) == 0, capsys.readouterr().out


def test_the_islands_joint_links_kernel_matches_its_numpy_reference():
    """islands.joint_links_flat (one compiled pass) gives the rows a numpy reference gives:
    unbroken joints only, 'driving' for a running motor but never for the mouse joint."""
    import physics
    from physics.step.islands import joint_links_flat
    from physics.store.joints import BROKEN, MOUSE
    w = physics.World()
    a = w.add_body(physics.Polygon.box(1, 1), position=(0, 0))
    b = w.add_body(physics.Polygon.box(1, 1), position=(1, 0))
    c = w.add_body(physics.Circle(0.3), position=(2, 0))
    w.add_joint("revolute", a, b, anchor=(0.5, 0.0), motor_speed=1.0, max_motor_torque=5.0)
    w.add_joint("revolute", b, c, anchor=(1.5, 0.0), motor_speed=0.0, max_motor_torque=5.0)
    w.add_joint("weld", c, None, anchor=(2.0, 0.0))
    w.add_joint("mouse", a, None, target=(0.0, 1.0))
    J = w._store.joints
    J.view.flags[2] |= BROKEN
    out = np.zeros((8, 3), np.int64)
    k = joint_links_flat(*J.arrays.flat, J.n, out)
    n, V = J.n, J.view
    keep = (V.flags[:n] & BROKEN) == 0
    driving = (V.max_motor[:n] > 0.0) & (V.motor_speed[:n] != 0.0) & (V.kind[:n] != MOUSE)
    want = np.c_[V.a[:n][keep], V.b[:n][keep], driving[keep]]
    assert k == 3 and np.array_equal(out[:k], want)
    assert list(want[:, 2]) == [1, 0, 0]


def test_optional_joints_compiles_only_the_variant_a_world_needs():
    """store/optional.py: a caller given the joint table's arrays compiles its callee for the
    joints' view only, and one given None for None only ('if JF is None' in the caller compiled
    both: numba prunes it only when the type is None)."""
    from numba import njit

    from physics.store.optional import optional_joints

    @njit
    def rows(J):
        return -1 if J is None else J.a.shape[0]

    @njit
    def caller(JF, JI):
        return rows(optional_joints(JF, JI))

    s = Store()
    s.joints.add()
    assert caller(*s.joints.arrays.flat) == s.joints.capacity
    assert len(rows.signatures) == 1
    assert caller(None, None) == -1
    assert len(rows.signatures) == 2
