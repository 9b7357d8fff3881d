"""Declared parameters of solver modes: name, default, range, meaning.

One declaration serves validation (world API and scene files), the sandbox
sliders and the benchmark sweeps.
"""
from __future__ import annotations

import math
from dataclasses import dataclass


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
        """Validated value of the declared type, or ValueError saying why."""
        t = self.type
        if t is bool:
            if isinstance(value, bool):
                return value
            raise ValueError(f"setting '{self.name}' must be true or false, got {value!r}")
        if t is str:
            if value in self.choices:
                return value
            raise ValueError(f"setting '{self.name}' must be one of {list(self.choices)}, got {value!r}")
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ValueError(f"setting '{self.name}' must be a number, got {value!r}")
        if not math.isfinite(value):
            raise ValueError(f"setting '{self.name}' must be finite, got {value!r}")
        if t is int:
            if float(value) != int(value):
                raise ValueError(f"setting '{self.name}' must be an integer, got {value!r}")
            value = int(value)
        else:
            value = float(value)
        if not math.isfinite(value):
            raise ValueError(f"setting '{self.name}' must be finite, got {value!r}")
        if self.lo is not None and value < self.lo:
            raise ValueError(f"setting '{self.name}' must be >= {self.lo}, got {value!r}")
        if self.hi is not None and value > self.hi:
            raise ValueError(f"setting '{self.name}' must be <= {self.hi}, got {value!r}")
        return value


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
    """Dict-like view of one solver mode's parameters, validated on assignment."""

    def __init__(self, store: ModeValues, solver: str):
        self._store = store
        self._solver = solver
        self._decl = store.decl
        self._values = store.values

    def _check(self, key):
        if key not in self._decl:
            raise KeyError(f"solver '{self._solver}' has no setting {key!r}; it has {list(self._decl)}")

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
        return key in self._decl

    def items(self):
        return [(k, self._values[k]) for k in self._decl]

    def keys(self):
        return list(self._decl)

    def declared(self):
        return dict(self._decl)

    def update(self, other=(), **kw):
        for k, v in dict(other, **kw).items():
            self[k] = v

    def to_dict(self) -> dict:
        return dict(self.items())

    def __repr__(self):
        return f"ModeSettings({self._solver}, {self.to_dict()})"
