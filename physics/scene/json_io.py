"""Strict, bounded JSON in and atomic JSON out for scene files.

Python's json module accepts NaN, Infinity and overflowing literals such as
1e400 (which become inf); scene files must not, so non-finite numbers parse
to a marker that the checks report with its JSON path.  Nothing here ever
evaluates or unpickles anything.
"""
from __future__ import annotations

import json
import math
import os
import tempfile


class NonFinite:
    """Stands in for a NaN/Infinity literal so parsing continues and every one is reported."""

    __slots__ = ("text",)

    def __init__(self, text: str):
        self.text = text

    def __repr__(self):
        return self.text


def _float(text: str):
    x = float(text)
    return x if math.isfinite(x) else NonFinite(text)


def parse(text: str):
    """json.loads that turns NaN, Infinity and overflowing numbers into NonFinite markers."""
    return json.loads(text, parse_constant=NonFinite, parse_float=_float)


def read_text(path, max_bytes: int) -> str:
    """The file's text, refusing oversized files before reading them (OSError, ValueError)."""
    size = os.stat(path).st_size
    if size > max_bytes:
        raise ValueError(f"file is {size / 2**20:.1f} MB; scene files are limited to {max_bytes / 2**20:.0f} MB")
    with open(path, "rb") as f:
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
        if key in ("bodies", "springs") and value:
            lines.append(f"  {json.dumps(key)}: [")
            rows = [json.dumps(v, allow_nan=False) for v in value]
            lines += [f"    {r}," for r in rows[:-1]] + [f"    {rows[-1]}"]
            lines.append(f"  ]{comma}")
        else:
            lines.append(f"  {json.dumps(key)}: {json.dumps(value, allow_nan=False)}{comma}")
    lines.append("}")
    return "\n".join(lines) + "\n"


def write_atomic(path, text: str) -> None:
    """Write to a temporary file in the same directory, then rename over ``path``.

    A crash leaves either the old file or the new one, never half of either;
    fsync makes the rename durable on filesystems that reorder writes.
    """
    path = os.fspath(path)
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".", suffix=".tmp", dir=folder)
    try:
        # mkstemp makes the file private (0600); a scene should keep the old file's mode
        try:
            mode = os.stat(path).st_mode & 0o777
        except FileNotFoundError:
            mode = 0o644
        os.chmod(tmp, mode)
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
