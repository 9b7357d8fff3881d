"""Every problem in scene data, each as (JSON path, reason).

Order of checks: format and version (if the file is not a version-1 scene,
nothing else is worth reporting), the body limit, non-finite numbers, the
JSON Schema, and last the hand checks for what a schema cannot express:
shapes (convexity, degeneracy), duplicate and dangling names, the solver and
its declared settings.  Hand checks skip any part the schema already
rejected, so one mistake is reported once.
"""
from __future__ import annotations

import json
import re

from jsonschema import Draft202012Validator

from .. import solvers
from ..errors import SceneError
from ..geometry.shapes import Circle, Polygon
from . import schema as fmt
from .json_io import NonFinite

_VALIDATOR = None
_IDENT = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_TYPE_NAMES = {dict: "an object", list: "an array", str: "a string", bool: "a boolean", type(None): "null",
               int: "a number", float: "a number", NonFinite: "a non-finite number"}


def validator() -> Draft202012Validator:
    global _VALIDATOR
    if _VALIDATOR is None:
        Draft202012Validator.check_schema(fmt.SCHEMA)
        _VALIDATOR = Draft202012Validator(fmt.SCHEMA)
    return _VALIDATOR


def json_path(parts) -> str:
    """('bodies', 12, 'shape', 'polygon') -> 'bodies[12].shape.polygon'."""
    out = ""
    for p in parts:
        if isinstance(p, int):
            out += f"[{p}]"
        elif _IDENT.match(p):
            out += f".{p}" if out else p
        else:
            out += f"[{json.dumps(p)}]"
    return out or "$"


class Rejected:
    """Paths the schema (or the NaN scan) already rejected; hand checks skip anything overlapping them."""

    def __init__(self, paths):
        self.paths = set(paths)
        self.prefixes = {p[:k] for p in self.paths for k in range(len(p) + 1)}

    def __contains__(self, path: tuple) -> bool:
        # a rejected path inside this subtree, or this path inside a rejected subtree
        return path in self.prefixes or any(path[:k] in self.paths for k in range(len(path)))


# -- format, limits, non-finite numbers -------------------------------------
def header_problems(data) -> list:
    if not isinstance(data, dict):
        return [((), f"a scene is a JSON object, got {_TYPE_NAMES.get(type(data), type(data).__name__)}")]
    out = []
    if data.get("format") != fmt.FORMAT:
        got = "missing" if "format" not in data else f"got {data['format']!r}"
        out.append((("format",), f"not a Stelkropp scene: expected \"format\": \"{fmt.FORMAT}\" ({got})"))
    if data.get("version") != fmt.VERSION or isinstance(data.get("version"), bool):
        got = "missing" if "version" not in data else f"got {data['version']!r}"
        out.append((("version",), f"unsupported version ({got}); this build reads version {fmt.VERSION}"))
    return out


def count_problem(data):
    bodies = data.get("bodies")
    if isinstance(bodies, list) and len(bodies) > fmt.MAX_BODIES:
        return (("bodies",), f"{len(bodies)} bodies; scenes are limited to {fmt.MAX_BODIES} bodies")
    return None


def nonfinite_problems(data, path=()) -> list:
    if isinstance(data, NonFinite):
        return [(path, f"{data.text} is not allowed: numbers must be finite")]
    if isinstance(data, dict):
        return [p for k, v in data.items() for p in nonfinite_problems(v, path + (k,))]
    if isinstance(data, list):
        return [p for i, v in enumerate(data) for p in nonfinite_problems(v, path + (i,))]
    return []


# -- the schema -----------------------------------------------------------
def schema_problems(data, nonfinite: Rejected) -> list:
    out = []
    for err in validator().iter_errors(data):
        path = tuple(err.absolute_path)
        if isinstance(err.instance, NonFinite) or path in nonfinite:
            continue
        out += _explain(err, path)
    return out


def _explain(err, path):
    """Schema errors in plain words (jsonschema's own messages repeat whole objects)."""
    v, inst, val = err.validator, err.instance, err.validator_value
    if v == "required":
        return [(path + (k,), "required field is missing") for k in val if k not in inst]
    if v == "additionalProperties":
        allowed = list(err.schema.get("properties", {}))
        return [(path + (k,), f"unknown key (allowed: {', '.join(allowed)})")
                for k in inst if k not in allowed]
    if v in ("minProperties", "maxProperties") and path[-1:] == ("shape",):
        return [(path, f"give exactly one of {', '.join(fmt.SCHEMA['$defs']['shape']['properties'])}")]
    if v == "type":
        want = [val] if isinstance(val, str) else val
        return [(path, f"expected {' or '.join(_article(t) for t in want)}, got "
                       f"{_TYPE_NAMES.get(type(inst), type(inst).__name__)} {_short(inst)}")]
    if v == "enum":
        return [(path, f"must be one of {', '.join(map(str, val))}; got {_short(inst)}")]
    if v == "const":
        return [(path, f"must be {json.dumps(val)}; got {_short(inst)}")]
    bounds = {"minimum": ">=", "maximum": "<=", "exclusiveMinimum": ">", "exclusiveMaximum": "<"}
    if v in bounds:
        return [(path, f"must be {bounds[v]} {val}; got {_short(inst)}")]
    if v in ("minItems", "maxItems"):
        return [(path, f"has {len(inst)} item{'s' if len(inst) != 1 else ''}; needs "
                       f"{'at least' if v == 'minItems' else 'at most'} {val}")]
    if v == "items" and val is False:
        return [(path, f"has {len(inst)} items; expected {len(err.schema.get('prefixItems', []))}")]
    if v == "minLength":
        return [(path, "must not be empty")]
    return [(path, err.message)]


def _article(t):
    return {"object": "an object", "array": "an array", "integer": "an integer", "null": "null"}.get(t, f"a {t}")


def _short(x):
    s = json.dumps(x) if not isinstance(x, NonFinite) else x.text
    return s if len(s) <= 60 else s[:57] + "..."


# -- hand checks ----------------------------------------------------------
def make_shape(spec):
    """The physics shape for a (schema-valid) shape object; ValueError if the geometry is bad."""
    (key, val), = spec.items()
    if key == "box":
        return Polygon.box(*val)
    if key == "polygon":
        return Polygon(val)
    if key == "regular":
        return Polygon.regular(val["sides"], val["radius"])
    if isinstance(val, dict):
        return Circle(val["radius"], val.get("offset", (0.0, 0.0)))
    return Circle(val)


def shape_problems(bodies, bad: Rejected):
    """(problems, shapes): shapes[i] is the built shape of body i, or None if it was not built."""
    out, shapes = [], []
    for i, b in enumerate(bodies):
        path = ("bodies", i, "shape")
        shapes.append(None)
        if path in bad or not isinstance(b, dict) or "shape" not in b:
            continue
        try:
            shapes[i] = make_shape(b["shape"])
        except ValueError as exc:
            out.append((path + (next(iter(b["shape"])),), str(exc)))
    return out, shapes


def name_problems(items, what: str, section: str, bad: Rejected) -> list:
    out, first = [], {}
    for i, item in enumerate(items):
        name = item.get("name") if isinstance(item, dict) else None
        if not isinstance(name, str) or (section, i, "name") in bad:
            continue
        if name in first:
            out.append(((section, i, "name"), f"duplicate {what} name {name!r} (first used by {section}[{first[name]}])"))
        else:
            first[name] = i
    return out


def spring_problems(bodies, springs, bad: Rejected) -> list:
    names = {b["name"] for b in bodies if isinstance(b, dict) and isinstance(b.get("name"), str)}
    out = []
    for i, sp in enumerate(springs):
        if not isinstance(sp, dict):
            continue
        for end in ("a", "b"):
            ref = sp.get(end)
            if isinstance(ref, str) and ref and ("springs", i, end) not in bad and ref not in names:
                out.append((("springs", i, end), f"no body named {ref!r}"))
        if isinstance(sp.get("a"), str) and sp.get("a") == sp.get("b"):
            out.append((("springs", i, "b"), "a spring needs two different bodies (or null for a world point)"))
    return out


def solver_problems(world: dict, bad: Rejected) -> list:
    name = world.get("solver", fmt.WORLD_DEFAULTS["solver"])
    if not isinstance(name, str) or ("world", "solver") in bad:
        return []
    try:
        mode = solvers.get(name)
    except ValueError:
        return [(("world", "solver"), f"unknown solver {name!r}; this build has: {', '.join(solvers.available())}")]
    except ImportError as exc:
        return [(("world", "solver"), f"solver {name!r} is not available in this build ({exc})")]
    settings = world.get("settings", {})
    if not isinstance(settings, dict):
        return []
    out = []
    for key, value in settings.items():
        path = ("world", "settings", key)
        if path in bad:
            continue
        if key not in mode.settings:
            out.append((path, f"solver {name!r} has no setting {key!r}; it has: {', '.join(mode.settings)}"))
            continue
        try:
            mode.settings[key].coerce(value)
        except ValueError as exc:
            out.append((path, str(exc)))
    return out


def hand_problems(data, bad: Rejected):
    """(problems, shapes) for the checks a schema cannot express."""
    bodies = data.get("bodies") if isinstance(data.get("bodies"), list) else []
    springs = data.get("springs") if isinstance(data.get("springs"), list) else []
    world = data.get("world") if isinstance(data.get("world"), dict) else {}
    out, shapes = shape_problems(bodies, bad)
    out += name_problems(bodies, "body", "bodies", bad)
    out += name_problems(springs, "spring", "springs", bad)
    out += spring_problems(bodies, springs, bad)
    out += solver_problems(world, bad)
    return out, shapes


def check(data):
    """(problems, shapes) for scene data; problems are (json_path_string, reason) in document order."""
    problems = header_problems(data)
    if problems:
        return _finish(problems), []
    too_many = count_problem(data)
    if too_many:
        return _finish([too_many]), []
    problems = nonfinite_problems(data)
    problems += schema_problems(data, Rejected(p for p, _ in problems))
    more, shapes = hand_problems(data, Rejected(p for p, _ in problems))
    return _finish(problems + more), shapes


def scene_error(source, problems) -> SceneError:
    """One SceneError for ``problems`` [(json_path, reason)]: names ``source``, lists each."""
    n = len(problems)
    lines = [f"{source}: {n} problem{'s' if n != 1 else ''} in scene"]
    lines += [f"  {p}: {r}" for p, r in problems]
    return SceneError("\n".join(lines), problems=problems, path=source)


def _finish(problems):
    seen, out = set(), []
    for path, reason in sorted(problems, key=lambda p: _sort_key(p[0])):
        item = (json_path(path), reason)
        if item not in seen:
            seen.add(item)
            out.append(item)
    return out


def _sort_key(path):
    # ints before strings at the same depth would be arbitrary; compare as (type, value) pairs
    return tuple((0, p, "") if isinstance(p, int) else (1, 0, p) for p in path)
