"""The named columns kernels index the store's 2-D tables with (physics/store/columns.py) are the
columns store/table.py really lays each field out in: every field's first column, and each view of
a table reads and writes the same memory as its columns."""
import numpy as np
import pytest

import physics.store.columns as cols
from physics.store import BODY_FIELDS, FIXTURE_FIELDS, SPRING_FIELDS, VERT_FIELDS, Store

TABLES = {"B_": BODY_FIELDS, "FX_": FIXTURE_FIELDS, "S_": SPRING_FIELDS, "V_": VERT_FIELDS}
# field -> constant name where the plain upper-case name is not the constant's
RENAMED = {"B_": {"f": "FORCE_X", "x": "X", "v": "VX", "com": "COM_X"},
           "FX_": {"center": "CENTER_X", "wcenter": "WCENTER_X"},
           "S_": {"la": "LA_X", "lb": "LB_X"},
           "V_": {k: k.upper() + "_X" for k in VERT_FIELDS}}


@pytest.mark.parametrize("prefix", TABLES)
def test_every_field_has_its_first_column(prefix):
    for name, (which, col, _) in cols.layout(TABLES[prefix]).items():
        const = prefix + RENAMED[prefix].get(name, name.upper())
        assert getattr(cols, const) == col, (const, which, col)


def test_a_column_is_the_field_it_names():
    s = Store()
    oid, slot = s.bodies.add()
    arrays = s.bodies.arrays
    arrays.F[slot, cols.B_VY] = 2.5
    arrays.I[slot, cols.B_AWAKE] = 1
    assert s.bodies.view.v[slot, 1] == 2.5 and s.bodies.view.awake[slot] == 1
    s.bodies.view.aabb[slot] = (1.0, 2.0, 3.0, 4.0)
    assert list(arrays.F[slot, cols.B_AABB:cols.B_AABB + 4]) == [1.0, 2.0, 3.0, 4.0]
    fid, f = s.fixtures.add()
    s.fixtures.view.mask[f] = np.uint64(2**64 - 1)  # filter bits: uint64 over an int64 column
    assert s.fixtures.arrays.I[f, cols.FX_MASK] == -1
