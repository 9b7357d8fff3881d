"""How problems in scene data are written: JSON paths, short previews of values, and one
SceneError whose size is bounded however hostile the input.

A problem is (path, reason): ``path`` a tuple of keys and indices while checking,
a string such as ``bodies[12].shape.polygon`` once finished.  A file with two
million bad elements must not produce a message of megabytes, so at most
``schema.MAX_PROBLEMS`` problems are kept (the message says when there were
more) and each path and reason is clipped.
"""
from __future__ import annotations

import json
import re

from ..errors import SceneError
from . import schema as fmt
from .json_io import NonFinite

_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")  # fullmatch: "$" would let a trailing newline through
MAX_PATH_CHARS = 200
MAX_REASON_CHARS = 400
_PREVIEW_CHARS = 60


def json_path(parts) -> str:
    """('bodies', 12, 'shape', 'polygon') -> 'bodies[12].shape.polygon' ('$' for the root)."""
    out = ""
    for p in parts:
        if isinstance(p, int):
            out += f"[{p}]"
        elif not isinstance(p, str):  # scene_from_dict may be handed any dict
            out += f"[{clip(repr(p), MAX_PATH_CHARS)}]"
        elif _IDENT.fullmatch(p):
            out += f".{p}" if out else p
        else:
            out += f"[{json.dumps(p[:MAX_PATH_CHARS])}]"  # escapes quotes, control characters, surrogates
        if len(out) > MAX_PATH_CHARS:
            break
    return clip(out, MAX_PATH_CHARS) or "$"


def clip(text: str, limit: int) -> str:
    """``text``, or its start and a note of its length if longer than ``limit`` characters."""
    return text if len(text) <= limit else f"{text[:limit - 30]}... ({len(text)} characters)"


def type_name(x) -> str:
    """'an object', 'a number', ... for a parsed JSON value (or whatever scene_from_dict was given)."""
    if isinstance(x, bool):
        return "a boolean"
    if isinstance(x, NonFinite):
        return "a non-finite number"
    for t, name in ((dict, "an object"), (list, "an array"), (str, "a string"), ((int, float), "a number")):
        if isinstance(x, t):
            return name
    return "null" if x is None else type(x).__name__


def quoted(name) -> str:
    """A name or key as Python quotes it ('plank9'), clipped; escapes make any string printable."""
    return clip(repr(name[: _PREVIEW_CHARS + 1] if isinstance(name, str) else name), _PREVIEW_CHARS)


def preview(x) -> str:
    """A value as short JSON for a message: containers with many items are described, not written."""
    if isinstance(x, NonFinite):
        return x.text
    if isinstance(x, str):
        return clip(json.dumps(x[:_PREVIEW_CHARS + 1]), _PREVIEW_CHARS)
    if isinstance(x, (list, dict)) and not _small(x):
        return f"{type_name(x)} of {len(x)} {'items' if isinstance(x, list) else 'keys'}"
    try:
        text = json.dumps(x, default=repr)
    except (TypeError, ValueError):  # not JSON data at all (scene_from_dict is given any object)
        text = repr(x)
    return clip(text, _PREVIEW_CHARS)


def _small(x, budget: int = 24) -> bool:
    """Whether ``x`` holds at most ``budget`` keys and values, no long string (walked without recursion)."""
    stack = [x]
    while stack:
        v = stack.pop()
        budget -= 1
        if budget < 0:
            return False
        if isinstance(v, (list, dict)):
            if len(v) > budget:
                return False
            stack += [*v, *v.values()] if isinstance(v, dict) else v
        elif isinstance(v, str) and len(v) > _PREVIEW_CHARS:
            return False
    return True


def finish(problems) -> list:
    """Problems as (path string, reason) in document order, duplicates dropped, at most
    MAX_PROBLEMS + 1 kept (one more than listed tells scene_error there were more)."""
    seen, out = set(), []
    for path, reason in sorted(problems, key=lambda p: _sort_key(p[0])):
        item = (json_path(path), reason)
        if item not in seen:
            seen.add(item)
            out.append(item)
            if len(out) > fmt.MAX_PROBLEMS:
                break
    return out


def _sort_key(path):
    # ints before strings at the same depth would be arbitrary; compare as (type, value) pairs
    return tuple((0, p, "") if isinstance(p, int) else (1, 0, p if isinstance(p, str) else repr(p)) for p in path)


def scene_error(source, problems) -> SceneError:
    """One SceneError for finished ``problems`` [(path string, reason)]: names ``source`` and lists
    each, at most MAX_PROBLEMS of them, each path and reason clipped."""
    n = len(problems)
    problems = [(clip(p, MAX_PATH_CHARS), clip(r, MAX_REASON_CHARS)) for p, r in problems[: fmt.MAX_PROBLEMS]]
    if n > fmt.MAX_PROBLEMS:
        head = f"{source}: more than {fmt.MAX_PROBLEMS} problems in scene; the first {fmt.MAX_PROBLEMS} found:"
    else:
        head = f"{source}: {n} problem{'s' if n != 1 else ''} in scene"
    lines = [clip(head, 2 * MAX_PATH_CHARS)] + [f"  {p}: {r}" for p, r in problems]
    return SceneError("\n".join(lines), problems=problems, path=source)
