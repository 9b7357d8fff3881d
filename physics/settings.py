"""Declared parameters of solver modes: name, default, range, meaning.

One declaration serves validation (world API and scene files), the sandbox
sliders and the benchmark sweeps.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .validate import as_float, is_number, shown


@dataclass(frozen=True)
class Setting:
    name: str
    default: float | int | bool | str
    lo: float | None = None
    hi: float | None = None
    doc: str = ""
    choices: tuple = ()

    @property
    def type(self):
        return type(self.default)

    def coerce(self, value):
        """Validated value of the declared type, or ValueError saying why: a bool setting takes
        True/False (numpy's too), a choice one of ``choices``, a number any real number (numpy's
        too; not a string, bytes or bool) within [lo, hi], an integer setting a whole one."""
        t = self.type
        who = f"setting '{self.name}'"
        if t is bool:
            if isinstance(value, (bool, np.bool_)):
                return bool(value)
            raise ValueError(f"{who} must be true or false, got {shown(value)}")
        if t is str:
            if isinstance(value, str) and value in self.choices:
                return value
            raise ValueError(f"{who} must be one of {list(self.choices)}, got {shown(value)}")
        if not is_number(value):
            raise ValueError(f"{who} must be a number, got {shown(value)}")
        x = as_float(value, who)
        if not math.isfinite(x):
            raise ValueError(f"{who} must be finite, got {shown(value)}")
        if t is int:
            if x != math.floor(x):
                raise ValueError(f"{who} must be an integer, got {shown(value)}")
            value = int(x)
        else:
            value = x
        if self.lo is not None and value < self.lo:
            raise ValueError(f"{who} must be >= {self.lo}, got {shown(value)}")
        if self.hi is not None and value > self.hi:
            raise ValueError(f"{who} must be <= {self.hi}, got {shown(value)}")
        return value


class UnknownSetting(KeyError, ValueError):
    """A setting name the solver mode does not declare: a KeyError (dict-like use) and a
    ValueError (the API's error for bad input), whose message names the setting."""

    def __str__(self):
        return str(self.args[0]) if self.args else ""


def declare(*settings: Setting) -> dict[str, Setting]:
    return {s.name: s for s in settings}


class ModeValues:
    """The values of one mode's settings in one world, and a version bumped on every change
    (so the step reloads the mode's parameter record only when a value changed)."""

    __slots__ = ("decl", "values", "version")

    def __init__(self, decl: dict[str, Setting]):
        self.decl = decl
        self.values = {k: s.default for k, s in decl.items()}
        self.version = 0

    def assign(self, key, value) -> None:
        self.values[key] = self.decl[key].coerce(value)
        self.version += 1


class ModeSettings:
    """Dict-like view of one solver mode's parameters, validated on assignment; each setting is
    also an attribute (``world.settings.iterations = 20``).  An unknown name raises, for items
    and attributes alike (UnknownSetting naming it), instead of being set and then ignored."""

    __slots__ = ("_store", "_solver", "_decl", "_values")

    def __init__(self, store: ModeValues, solver: str):
        object.__setattr__(self, "_store", store)
        object.__setattr__(self, "_solver", solver)
        object.__setattr__(self, "_decl", store.decl)
        object.__setattr__(self, "_values", store.values)

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        try:
            return self[name]
        except UnknownSetting as err:
            raise AttributeError(str(err)) from None

    def __setattr__(self, name, value):
        if name in self.__slots__:  # copy and pickle restore the view's own fields
            object.__setattr__(self, name, value)
        else:
            self[name] = value

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._decl))

    def _check(self, key):
        if not isinstance(key, str) or key not in self._decl:
            raise UnknownSetting(f"solver '{self._solver}' has no setting {shown(key)}; it has {list(self._decl)}")

    def __getitem__(self, key):
        self._check(key)
        return self._values[key]

    def __setitem__(self, key, value):
        self._check(key)
        self._store.assign(key, value)

    def __iter__(self):
        return iter(self._decl)

    def __len__(self):
        return len(self._decl)

    def __contains__(self, key):
        return isinstance(key, str) and key in self._decl

    def items(self):
        return [(k, self._values[k]) for k in self._decl]

    def keys(self):
        return list(self._decl)

    def declared(self):
        return dict(self._decl)

    def update(self, other=(), **kw):
        """Assign several settings, all or none: every value is checked before any is applied
        (UnknownSetting or ValueError for the first bad one)."""
        try:
            new = dict(other, **kw)
        except (TypeError, ValueError):
            raise ValueError(f"settings.update: expected a mapping of setting names to values, "
                             f"got {shown(other)}") from None
        checked = {}
        for k, v in new.items():
            self._check(k)
            checked[k] = self._decl[k].coerce(v)
        for k, v in checked.items():
            self._store.assign(k, v)

    def to_dict(self) -> dict:
        return dict(self.items())

    def __repr__(self):
        return f"ModeSettings({self._solver}, {self.to_dict()})"
