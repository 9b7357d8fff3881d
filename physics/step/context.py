"""The step context: the per-step scalars every stage reads, as one record.

Kernels take the context (a one-element numpy structured array; inside a kernel
``c = ctx[0]`` and ``c.dt``, ``c.nc``, ...) instead of long positional lists, and
a solver mode's kernels take one more record, the mode's parameters: its
declared settings (physics/solvers/*: ``Setting``) plus what the mode derives
from them for this step (sub-step length, softness coefficients, ...).

Writing a record field from Python through the record costs about 1 us, through
a prepared one-element field view about 0.15 us; both records keep such views
and are refreshed only where something changed (counts every step, settings
when a setting was assigned).
"""
from __future__ import annotations

import numpy as np

#: (name, dtype): the step context's fields
CONTEXT_FIELDS = (
    ("step", np.int64),           # world.steps when the step began
    ("dt", np.float64),           # step length (s)
    ("inv_dt", np.float64),
    ("n", np.int64),              # live bodies
    ("nc", np.int64),             # contact rows after the narrow phase
    ("ns", np.int64),             # springs
    ("nj", np.int64),             # joints
    ("gx", np.float64),           # gravity (m/s^2)
    ("gy", np.float64),
    ("spec", np.float64),         # speculative distance (m)
    ("slop", np.float64),         # linear slop (m): contacts within it count as touching
    ("sleep_linear", np.float64),  # sleep thresholds (m/s, rad/s, s)
    ("sleep_angular", np.float64),
    ("time_to_sleep", np.float64),
    ("integrator", np.int64),     # code in options.INTEGRATORS
    ("narrowphase", np.int64),    # code in options.NARROWPHASES
    ("push_speed", np.float64),   # the mode's push-out speed cap (m/s): the energy guard's allowance
    ("threads", np.int64),        # threads the step may split its wide loops over (physics/threads.py)
)


class Record:
    """A one-element structured array with fast per-field writes (``rec.set(name, v)``)."""

    def __init__(self, fields):
        self.dtype = np.dtype([(name, dt) if shape is None else (name, dt, shape)
                               for name, dt, shape in _normalise(fields)], align=True)
        self.array = np.zeros(1, self.dtype)
        self._views = {name: self.array[name] for name in self.dtype.names}

    def set(self, name: str, value) -> None:
        self._views[name][0] = value

    def get(self, name: str):
        return self._views[name][0]

    def __repr__(self):
        return f"{type(self).__name__}({ {k: self.get(k) for k in self.dtype.names} })"


def _normalise(fields):
    for f in fields:
        if len(f) == 2:
            yield f[0], f[1], None
        else:
            yield f


class StepContext(Record):
    """The common per-step scalars (CONTEXT_FIELDS), one record per world."""

    def __init__(self):
        super().__init__(CONTEXT_FIELDS)


def setting_dtype(setting):
    """The record dtype of a declared setting: bool, int64, float64, or int64 (choice index)."""
    t = setting.type
    if t is bool:
        return np.bool_
    if t is int or t is str:
        return np.int64
    return np.float64


class ModeParams(Record):
    """A solver mode's parameters for its kernels: its settings and its derived per-step values.

    ``settings`` is the mode's declaration (name -> Setting); a string setting is
    stored as the index of its value in ``choices``.  ``derived`` lists extra
    fields as (name, dtype) or (name, dtype, shape).  ``version`` is the settings
    version last loaded (see physics/settings.py ModeValues).
    """

    def __init__(self, settings: dict, derived=(), record: dict | None = None):
        self._settings = settings
        record = settings if record is None else record
        super().__init__([(name, setting_dtype(s)) for name, s in record.items()] + list(derived))
        for name, s in record.items():  # a shared record's fields this mode lacks: their defaults
            if name not in settings:
                self.set(name, s.choices.index(s.default) if s.type is str else s.default)
        self.version = -1
        self.values: dict = {}  # the settings as given (choices as strings), for derive()
        self.push_speed = 0.0  # the mode's push-out speed cap with these settings (Pipeline.params)

    def load(self, values: dict, version: int) -> None:
        for name, s in self._settings.items():
            v = values[name]
            self.set(name, s.choices.index(v) if s.type is str else v)
        self.values = values
        self.version = version
