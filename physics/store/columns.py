"""Named columns of the store's 2-D tables, for kernels that take a table as two arrays.

store/table.py lays each table out as a float64 array ``F`` and an int64 array ``I``, one row
per entry, the fields in their declaration order (a field of shape (2,) takes two columns).
A kernel reads ``BF[i, B_X]`` instead of ``B.x[i, 0]``: two arrays per table instead of a
namedtuple of twenty, which shrinks every call's IR and its compile time (docs/flat-step.md).
The constants are written out so a reader sees them; tests/test_store_columns.py checks them
against the layout the tables really have.
"""
from __future__ import annotations

import numpy as np

from .table import separate


def layout(fields: dict) -> dict[str, tuple[str, int, int]]:
    """{field: ("F" or "I", first column, width)} as store/table.py lays ``fields`` out (the fields
    of two or more dimensions per entry are arrays of their own: not listed)."""
    out, fc, ic = {}, 0, 0
    for name, (shape, dtype) in fields.items():
        if separate(shape):  # its own array (Columns.X), no columns
            continue
        w = int(np.prod(shape))
        if np.dtype(dtype).kind == "f":
            out[name] = ("F", fc, w)
            fc += w
        else:
            out[name] = ("I", ic, w)
            ic += w
    return out


# the body table (store/bodies.py); F:
B_X, B_Y, B_Q, B_VX, B_VY, B_W, B_M, B_INERTIA, B_INV_M, B_INV_I, B_DENSITY = range(11)
B_E, B_MU_S, B_MU_D, B_RADIUS, B_COM_X, B_COM_Y, B_BOUND_R = range(11, 18)
B_AABB = 18            # min x, min y, max x, max y: B_AABB .. B_AABB + 3
B_SLEEP_T, B_FORCE_X, B_FORCE_Y, B_TAU = range(22, 26)
# ... I:
B_KIND, B_SHAPE, B_VSTART, B_VCOUNT, B_AWAKE, B_ISLAND, B_ID = range(7)

# the fixture table (store/fixtures.py); F:
FX_RADIUS, FX_CENTER_X, FX_CENTER_Y, FX_WCENTER_X, FX_WCENTER_Y = range(5)
FX_DENSITY, FX_E, FX_MU_S, FX_MU_D, FX_AABB = range(5, 10)   # (ghost, wghost: arrays of their own)
# ... I:
FX_BODY, FX_KIND, FX_AWAKE, FX_SHAPE, FX_VSTART, FX_VCOUNT, FX_CATEGORY, FX_MASK, FX_GROUP, FX_SENSOR, \
    FX_ID = range(11)

# the spring table (store/springs.py); F:
S_LA_X, S_LA_Y, S_LB_X, S_LB_Y, S_K, S_C, S_REST = range(7)
# ... I:
S_A, S_B, S_ID = range(3)

# the vertex pool (store/vertices.py); F only:
V_LOCAL_X, V_LOCAL_Y, V_NORMAL_X, V_NORMAL_Y, V_WORLD_X, V_WORLD_Y, V_WNORMAL_X, V_WNORMAL_Y = range(8)
