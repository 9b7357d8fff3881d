"""Strict, bounded JSON in and canonical JSON text out for scene files.

Python's json module accepts NaN, Infinity, overflowing literals such as
1e400 (which become inf), integers of any length, and repeated keys (the
last one wins).  Scene files must not: numbers that are not finite floats
parse to a ``NonFinite`` marker and objects that repeat a key to a
``Duplicates`` dict, and the checks report each with its JSON path, so one
pass lists them all.  Nothing here ever evaluates or unpickles anything.
"""
from __future__ import annotations

import json
import math
import os
import re

from .file_kind import open_regular


class NonFinite:
    """Stands in for a number that is no finite float (NaN, Infinity, 1e400, a 400-digit
    integer) so parsing continues and every one is reported; ``text`` is the literal, shortened."""

    __slots__ = ("text", "integer")

    def __init__(self, text: str, integer: bool = False):
        self.text = text if len(text) <= 40 else f"{text[:12]}...{text[-6:]} ({len(text)} characters)"
        self.integer = integer

    @property
    def reason(self) -> str:
        """Why the number is refused, for the problem list."""
        if self.integer:
            return f"{self.text} is beyond the range of a float (about 1.8e308)"
        return f"{self.text} is not allowed: numbers must be finite"

    def __repr__(self):
        return self.text


class Duplicates(dict):
    """A JSON object that gives a key more than once: the last value of each key, plus
    ``repeated``, the keys given more than once (the checks report each with its path)."""

    __slots__ = ("repeated",)


def _float(text: str):
    x = float(text)
    return x if math.isfinite(x) else NonFinite(text)


def _int(text: str):
    # more than 309 digits is beyond the largest float (and past 4300 Python refuses to convert)
    if len(text) > 310:
        return NonFinite(text, integer=True)
    v = int(text)
    try:
        float(v)
    except OverflowError:
        return NonFinite(text, integer=True)
    return v


def _object(pairs):
    d = dict(pairs)
    if len(d) == len(pairs):
        return d
    out = Duplicates(d)
    seen, out.repeated = set(), []
    for key, _ in pairs:
        if key in seen and key not in out.repeated:
            out.repeated.append(key)
        seen.add(key)
    return out


_LONG_NUMBER = re.compile(r"[eE][+-]?\d{3}|\d{300}")


def parse(text: str):
    """json.loads, strictly: NaN, Infinity and numbers beyond float range become NonFinite,
    objects with a repeated key Duplicates; ValueError for invalid or too deeply nested JSON."""
    # json's own number parsing runs in C; a Python hook per number was most of the time of a 50 MB
    # file.  Integers of fewer than 300 digits are finite floats, and a float leaves the range only
    # with a 3-digit exponent or hundreds of digits, so the hooks (which keep the literal for the
    # message) run only when such a literal is present.  The rare rest (299 digits, then e99)
    # parses to inf, which value_problems refuses all the same, naming its path.
    hooks = {"parse_float": _float, "parse_int": _int} if _LONG_NUMBER.search(text) else {}
    try:
        return json.loads(text, parse_constant=NonFinite, object_pairs_hook=_object, **hooks)
    except RecursionError:  # json's C scanner recurses once per level (about 1000 allowed)
        raise ValueError("nested too deeply for a scene file") from None


def read_text(path, max_bytes: int) -> str:
    """The file's text, refusing oversized files before reading them (OSError, ValueError) and
    anything but a regular file (file_kind.NotRegularFile, an OSError)."""
    fd = open_regular(path)  # a FIFO or device would block or never end
    with os.fdopen(fd, "rb") as f:
        size = os.fstat(f.fileno()).st_size
        if size > max_bytes:
            raise ValueError(f"file is {size / 2**20:.1f} MB; scene files are limited to {max_bytes / 2**20:.0f} MB")
        data = f.read(max_bytes + 1)  # the file may have grown since stat
    if len(data) > max_bytes:
        raise ValueError(f"file is over the {max_bytes / 2**20:.0f} MB limit for scene files")
    return data.decode("utf-8")


def dumps(data) -> str:
    """Scene JSON: one line per body or spring keeps big scenes readable and diffable."""
    lines = ["{"]
    items = list(data.items())
    for i, (key, value) in enumerate(items):
        comma = "," if i < len(items) - 1 else ""
        if key in ("bodies", "springs", "joints") and value:
            lines.append(f"  {json.dumps(key)}: [")
            rows = [json.dumps(v, allow_nan=False) for v in value]
            lines += [f"    {r}," for r in rows[:-1]] + [f"    {rows[-1]}"]
            lines.append(f"  ]{comma}")
        else:
            lines.append(f"  {json.dumps(key)}: {json.dumps(value, allow_nan=False)}{comma}")
    lines.append("}")
    return "\n".join(lines) + "\n"
