"""ctypes binding of Stelkropp's Box2D v3 shim (``shim.c``): load once, declare every signature.

Numbers cross as C doubles and ints; arrays as numpy buffers (``as_ptr``). The record layouts of
the command stream are documented in ``shim.c`` / ``shim_ops.c`` and built by ``translate.py``.
"""
from __future__ import annotations

import ctypes as C

import numpy as np

from . import build as _build

# record and read-back widths, shared with shim.c / shim_read.c
OP_BODY, OP_SHAPE, OP_JOINT, OP_DESTROY_BODY, OP_DESTROY_JOINT, OP_VELOCITY = 1, 2, 3, 4, 5, 6
BODY_READ, MASS_READ, JOINT_READ, COUNTERS = 10, 4, 9, 7
SCHEDULERS = {"serial": 0, "shim": 1, "box2d": 2}
WORLD_PARAMS = 14

_LIBS: dict = {}

_D, _I, _P = C.c_double, C.c_int, C.c_void_p
_SIGNATURES = {
    "s2_world_create": (_P, [_P, _I]),
    "s2_world_destroy": (None, [_P]),
    "s2_error": (C.c_char_p, [_P]),
    "s2_exec": (_I, [_P, _P, _I, _P, _I]),
    "s2_step": (None, [_P, _D, _I, _I]),
    "s2_body_count": (_I, [_P]),
    "s2_joint_count": (_I, [_P]),
    "s2_read_bodies": (None, [_P, _P, _I]),
    "s2_read_mass": (None, [_P, _P, _I]),
    "s2_read_joints": (None, [_P, _P, _I]),
    "s2_counters": (None, [_P, _P]),
    "s2_set_velocity": (None, [_P, _I, _D, _D, _D]),
    "s2_set_target": (None, [_P, _I, _D, _D, _D, _D]),
    "s2_set_frame_a": (None, [_P, _I, _D, _D, _D]),
    "s2_last_step_ms": (_D, [_P]),
}


def load(box2d_src=None):
    """The loaded shim (``ctypes.CDLL``), building it first if needed. Raises ``BuildError``."""
    key = str(box2d_src)
    if key not in _LIBS:
        b = _build.build(box2d_src)
        lib = C.CDLL(str(b.library))
        for name, (res, args) in _SIGNATURES.items():
            f = getattr(lib, name)
            f.restype = res
            f.argtypes = args
        lib.build_info = b
        _LIBS[key] = lib
    return _LIBS[key]


def as_ptr(a: np.ndarray):
    """The data pointer of a C-contiguous numpy array (kept alive by the caller)."""
    assert a.flags.c_contiguous
    return a.ctypes.data_as(C.c_void_p)
