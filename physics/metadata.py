"""``world.metadata``: what a scene file says of itself, checked when it is set.

A plain dict let ``world.metadata["camera"] = {"center": "x"}`` through; save_scene then
wrote a file that load_scene refused.  This mapping refuses, when a key is set, any value of
a key the scene format gives a meaning to that a file could not hold: ``name`` and
``description`` (strings of valid Unicode, or None: not saved), ``camera`` ({"center": [x, y],
"zoom": z > 0}, both optional) and ``colors`` (the sandbox's body colours: body id ->
"#rrggbb").  Other keys are the caller's and are not saved.  Nested containers can still be
edited in place, so save_scene checks the same rules again before it writes (``problems``).
"""
from __future__ import annotations

import math
import re

from .validate import is_number, shown, text

_COLOR = re.compile(r"^#[0-9a-fA-F]{6}$")
CAMERA_KEYS = ("center", "zoom")


def _camera(value, field):
    if value is None:
        return
    if not isinstance(value, dict):
        raise ValueError(f"{field}: expected an object {{center, zoom}} or None, got {shown(value)}")
    for key, v in value.items():
        if key not in CAMERA_KEYS:
            raise ValueError(f"{field}[{key!r}]: unknown key (allowed: center, zoom)")
    if "center" in value:
        c = value["center"]
        ok = isinstance(c, (list, tuple)) and len(c) == 2 and all(is_number(x) and math.isfinite(x) for x in c)
        if not ok:
            raise ValueError(f"{field}['center']: expected [x, y], two finite numbers, got {shown(c)}")
    if "zoom" in value:
        z = value["zoom"]
        if not (is_number(z) and math.isfinite(z) and z > 0):
            raise ValueError(f"{field}['zoom']: expected a finite number > 0, got {shown(z)}")


def _colors(value, field):
    if value is None:
        return
    if not isinstance(value, dict):
        raise ValueError(f"{field}: expected a dict of body id -> \"#rrggbb\", got {shown(value)}")
    for k, v in value.items():
        if not isinstance(v, str) or not _COLOR.match(v):
            raise ValueError(f"{field}[{k!r}]: expected a colour \"#rrggbb\", got {shown(v)}")


def check(key, value, field: str = "metadata") -> None:
    """ValueError naming ``field[key]`` if a scene file could not hold ``value`` under ``key``."""
    where = f"{field}[{key!r}]"
    if key in ("name", "description"):
        if value is not None:
            text(value, where, empty=True)
    elif key == "camera":
        _camera(value, where)
    elif key == "colors":
        _colors(value, where)


class Metadata(dict):
    """A dict whose scene keys are checked as they are set (module docstring)."""

    def __init__(self, *args, **kw):
        super().__init__()
        self.update(*args, **kw)

    def __setitem__(self, key, value):
        check(key, value)
        super().__setitem__(key, value)

    def update(self, *args, **kw):
        for k, v in dict(*args, **kw).items():
            self[k] = v

    def setdefault(self, key, default=None):
        if key not in self:
            self[key] = default
        return self[key]

    def __ior__(self, other):
        self.update(other)
        return self

    def copy(self):
        return Metadata(self)
