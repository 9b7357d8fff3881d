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
