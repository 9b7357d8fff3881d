"""Declared parameters of solver modes: name, default, range, meaning.

One declaration serves validation (world API and scene files), the sandbox
sliders and the benchmark sweeps.
"""
from __future__ import annotations

import math
import warnings
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
    #: (old, new) pairs: a choice that was removed, read as the one that replaced it (with a
    #: DeprecationWarning), so that scene files and code written for it keep working
    legacy: tuple = ()

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
            for old, new in self.legacy:
                if isinstance(value, str) and value == old:
                    warnings.warn(f"{who}: {old!r} was removed; it is read as {new!r}", DeprecationWarning,
                                  stacklevel=3)
                    return new
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
    (so the step reloads the mode's parameter record only when a value changed).

    ``values`` are the declared defaults and what the user assigned (``explicit``: the names
    assigned); ``fitted`` are values the world chose from the scene's content (name ->
    (value, why): SolverMode.fit).  A fitted value is in force only where the user assigned
    nothing (a user's setting always wins); ``effective()`` is what the step runs with."""

    __slots__ = ("decl", "values", "version", "explicit", "fitted", "fitted_at", "refit")

    def __init__(self, decl: dict[str, Setting], refit=None):
        self.decl = decl
        self.values = {k: s.default for k, s in decl.items()}
        self.version = 0
        self.explicit: set = set()
        self.fitted: dict = {}
        self.fitted_at = None  # the world's edit count the fit was made at (Pipeline.fitted)
        self.refit = refit  # brings ``fitted`` up to date with the world's scene (World._settings_store)

    def __getstate__(self):  # a copy or an unpickled one is detached from its world (no refit)
        return {k: getattr(self, k) for k in self.__slots__ if k != "refit"}

    def __setstate__(self, state):
        self.refit = None
        for k, v in state.items():
            setattr(self, k, v)

    def assign(self, key, value) -> None:
        self.values[key] = self.decl[key].coerce(value)
        self.explicit.add(key)
        self.version += 1

    def unset(self, key) -> None:
        """Back to the default, or to the value the scene calls for."""
        self.values[key] = self.decl[key].default
        self.explicit.discard(key)
        self.version += 1

    def fit(self, chosen: dict) -> None:
        """The values the scene calls for now (name -> (value, why)); a change bumps the version."""
        if chosen != self.fitted:
            self.fitted = chosen
            self.version += 1

    def refresh(self) -> None:
        """Bring ``fitted`` up to date with the world's scene (nothing for a detached copy)."""
        if self.refit is not None:
            self.refit(self)

    def in_force(self) -> dict:
        """The fitted values in force (name -> (value, why)): those the user did not assign."""
        self.refresh()
        return {k: vw for k, vw in self.fitted.items() if k not in self.explicit}

    def effective(self) -> dict:
        """The values the step runs with: the fitted ones in force over ``values``."""
        chosen = self.in_force()
        if not chosen:
            return self.values
        out = dict(self.values)
        out.update({k: v for k, (v, _) in chosen.items()})
        return out


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
        """The value the step runs with: the user's, else the one the scene calls for (``chosen``),
        else the default."""
        self._check(key)
        chosen = self._store.in_force().get(key)
        return self._values[key] if chosen is None else chosen[0]

    def __setitem__(self, key, value):
        self._check(key)
        self._store.assign(key, value)

    def __iter__(self):
        return iter(self._decl)

    def __len__(self):
        return len(self._decl)

    def __contains__(self, key):
        return isinstance(key, str) and key in self._decl

    def __delitem__(self, key):
        """Forget the user's value: back to the default, or to the value the scene calls for."""
        self._check(key)
        self._store.unset(key)

    def items(self):
        eff = self._store.effective()
        return [(k, eff[k]) for k in self._decl]

    def chosen(self) -> dict:
        """The values the world chose from the scene's content and runs with, because the user set
        none of them: ``{"substeps": (8, "thin shapes: ...")}`` (SolverMode.fit).  Assigning a
        setting overrides its choice; ``del settings[name]`` hands it back."""
        return self._store.in_force()

    def fitted(self) -> dict:
        """Every value the scene calls for, in force or overridden by the user's (``chosen``)."""
        self._store.refresh()
        return dict(self._store.fitted)

    def is_set(self, key) -> bool:
        """Whether the user assigned this setting (a scene file's settings count as assigned)."""
        self._check(key)
        return key in self._store.explicit

    def assigned(self) -> dict:
        """What a scene file keeps: the values that differ from the default, and a value the user
        set over one the scene calls for (a chosen value is chosen again when the file is loaded)."""
        st = self._store
        st.refresh()
        return {k: st.values[k] for k in self._decl
                if not _same(st.values[k], self._decl[k].default) or (k in st.explicit and k in st.fitted)}

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


def _same(a, b) -> bool:
    """Equal as setting values (``coerce`` gives each setting one type, so the types match too)."""
    return type(a) is type(b) and a == b
