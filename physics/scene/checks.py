"""Every problem in scene data, each as (JSON path, reason).

Order of checks, cheap before expensive: format and version (if the data is not a version 1
or 2 scene, nothing else is worth reporting), the body limit and the work the scene asks for
(``budget``: list lengths only), the values themselves
(nesting depth, numbers that are no finite float, repeated keys, text that
is not valid Unicode), the JSON Schema, and last the hand checks for what a
schema cannot express: duplicate and dangling names, the solver and its
declared settings, and then shapes (convexity, degeneracy, size) and masses the
solver can represent, built only for bodies with nothing else wrong.  Each later check skips any part an earlier one
rejected, so one mistake is reported once.
"""
from __future__ import annotations

import itertools
import json
import math

import numpy as np

from jsonschema import Draft202012Validator, validators

from .. import solvers
from ..validate import checked_density
from . import schema as fmt
from .budget import work_problem
from .joints import joint_problems
from .shapes import fixture_fields, kind_of, make_shapes, shape_problem
from .json_io import Duplicates, NonFinite
from .problems import finish, preview, quoted, type_name
from .sandbox import sandbox_problems

_VALIDATOR = None
_VEC2 = {"$ref": "#/$defs/vec2"}
_NUMBER = (int, float)  # exact types: bool is no number here, as in JSON Schema


def _items(validator, items, instance, schema):
    """jsonschema's ``items``, with a shortcut for lists of points: a 100,000-point chain is
    checked in one loop instead of 100,000 schema descents; any list the loop doubts is
    descended as before, so the problems reported are the same."""
    if items == _VEC2 and isinstance(instance, list) and all(
            type(p) is list and len(p) == 2 and type(p[0]) in _NUMBER and type(p[1]) in _NUMBER
            for p in instance):
        return
    yield from _ITEMS(validator, items, instance, schema)


_ITEMS = Draft202012Validator.VALIDATORS["items"]
_Validator = validators.extend(Draft202012Validator, {"items": _items})


def validator() -> Draft202012Validator:
    global _VALIDATOR
    if _VALIDATOR is None:
        Draft202012Validator.check_schema(fmt.SCHEMA)
        _VALIDATOR = _Validator(fmt.SCHEMA)
    return _VALIDATOR


class Rejected:
    """Paths an earlier check already rejected; later checks skip anything overlapping them."""

    def __init__(self, paths):
        self.paths = set(paths)
        self.prefixes = {p[:k] for p in self.paths for k in range(len(p) + 1)}

    def __contains__(self, path: tuple) -> bool:
        # a rejected path inside this subtree, or this path inside a rejected subtree
        return path in self.prefixes or any(path[:k] in self.paths for k in range(len(path)))


# -- format, limits, the values themselves -------------------------------------
def header_problems(data) -> list:
    if not isinstance(data, dict):
        return [((), f"a scene is a JSON object, got {type_name(data)}")]
    out = []
    if data.get("format") != fmt.FORMAT:
        got = "missing" if "format" not in data else f"got {preview(data['format'])}"
        out.append((("format",), f"not a Stelkropp scene: expected \"format\": \"{fmt.FORMAT}\" ({got})"))
    version = data.get("version")
    if isinstance(version, bool) or not isinstance(version, int) or version not in fmt.VERSIONS:
        got = "missing" if "version" not in data else f"got {preview(data['version'])}"
        out.append((("version",), f"unsupported version ({got}); this build reads versions "
                                  f"{', '.join(map(str, fmt.VERSIONS))}"))
    return out


def count_problem(data):
    bodies = data.get("bodies")
    if isinstance(bodies, list) and len(bodies) > fmt.MAX_BODIES:
        return (("bodies",), f"{len(bodies)} bodies; scenes are limited to {fmt.MAX_BODIES} bodies")
    return None


def value_problems(data) -> tuple:
    """Values no scene may hold, wherever they are: nesting deeper than MAX_DEPTH, numbers that
    are no finite float, keys given twice in one object, strings that are not valid Unicode,
    and more values than any scene the work limit allows (MAX_VALUES; a list or object of more
    than MAX_ITEMS).  Walked with an explicit stack, so hostile nesting cannot exhaust Python's
    recursion.  Returns (problems, stop): stop when the data is too deep or too big for the
    schema and hand checks."""
    out, stack, stop, seen = [], [((), data)], False, 0
    while stack and len(out) <= fmt.MAX_PROBLEMS:
        path, v = stack.pop()
        seen += 1
        if seen > fmt.MAX_VALUES:
            return out + [(path, f"the scene holds more than {fmt.MAX_VALUES:,} values (numbers, strings, "
                                 "lists, objects); the largest scene the work limit allows holds about a million")], True
        if isinstance(v, (dict, list)) and len(path) >= fmt.MAX_DEPTH:
            out.append((path, f"nested more than {fmt.MAX_DEPTH} levels deep (a scene needs 7)"))
            stop = True
        elif isinstance(v, (dict, list)) and len(v) > fmt.MAX_ITEMS:
            return out + [(path, f"has {len(v):,} {'keys' if isinstance(v, dict) else 'items'}; no list or "
                                 f"object in a scene may have more than {fmt.MAX_ITEMS:,}")], True
        elif isinstance(v, dict):
            if isinstance(v, Duplicates):
                out += [(path + (k,), "duplicate key: this object gives it more than once") for k in v.repeated]
            for k, item in v.items():
                if not isinstance(k, str):
                    out.append((path + (k,), f"keys must be strings, got {type_name(k)}"))
                elif not _valid_text(k):
                    out.append((path + (k,), "key is not valid Unicode (it holds a lone surrogate)"))
                else:
                    stack.append((path + (k,), item))
        elif isinstance(v, list):
            plain = _plain_numbers(v) if len(path) < fmt.MAX_DEPTH - 2 else None
            if plain is not None:  # finite numbers or pairs of them: nothing to report inside
                seen += plain
            else:
                stack += [(path + (i,), item) for i, item in enumerate(v)]
        else:
            reason = _value_reason(v)
            if reason:
                out.append((path, reason))
    return out, stop


def _plain_numbers(v: list):
    """How many values a list of finite numbers, or of [x, y] pairs of them, holds (a chain's
    100,000 points: one numpy conversion, not 300,000 stack steps); None for any other list.
    Only what this walk looks for is excluded (non-finite or float-overflowing numbers, text,
    objects); types are the schema's business."""
    if not v or isinstance(v[0], str):
        return None
    try:
        a = np.asarray(v, dtype=np.float64)
    except (TypeError, ValueError, OverflowError):
        return None
    if not (a.ndim == 1 or (a.ndim == 2 and a.shape[1] == 2)) or not np.isfinite(a).all():
        return None
    if any(isinstance(x, str) for x in (v if a.ndim == 1 else (y for p in v for y in p))):
        return None  # numpy reads "1.5" as a number; a string must be walked (its text is checked)
    return a.size + (len(v) if a.ndim == 2 else 0)


def _value_reason(v):
    if isinstance(v, NonFinite):
        return v.reason
    if isinstance(v, float) and not math.isfinite(v):
        return f"{v} is not allowed: numbers must be finite"
    if isinstance(v, int) and not isinstance(v, bool) and v.bit_length() > 1000:
        try:
            float(v)
        except OverflowError:
            digits = int(v.bit_length() * math.log10(2)) + 1
            return f"an integer of about {digits} digits is beyond the range of a float (about 1.8e308)"
    if isinstance(v, str) and not _valid_text(v):
        return "not valid Unicode: holds a lone surrogate (an unpaired \\ud800-\\udfff escape)"
    return None


def _valid_text(s: str) -> bool:
    if s.isascii():
        return True
    try:
        s.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


# -- the schema -----------------------------------------------------------
def schema_problems(data, rejected: Rejected) -> list:
    out = []
    for err in validator().iter_errors(data):
        path = tuple(err.absolute_path)
        if isinstance(err.instance, NonFinite) or path in rejected:
            continue
        out += _explain(err, path)
        if len(out) > fmt.MAX_PROBLEMS:  # the rest would not be listed
            break
    return out


def _explain(err, path):
    """Schema errors in plain words (jsonschema's own messages repeat whole objects)."""
    v, inst, val = err.validator, err.instance, err.validator_value
    if v == "required":
        return [(path + (k,), "required field is missing") for k in val if k not in inst]
    if v == "additionalProperties":
        allowed = list(err.schema.get("properties", {}))
        unknown = itertools.islice((k for k in inst if k not in allowed), fmt.MAX_PROBLEMS + 1)
        return [(path + (k,), f"unknown key (allowed: {', '.join(allowed)})") for k in unknown]
    if v == "type":
        want = [val] if isinstance(val, str) else val
        return [(path, f"expected {' or '.join(_article(t) for t in want)}, got {type_name(inst)} {preview(inst)}")]
    if v == "enum":
        return [(path, f"must be one of {', '.join(map(str, val))}; got {preview(inst)}")]
    if v == "const":
        return [(path, f"must be {json.dumps(val)}; got {preview(inst)}")]
    bounds = {"minimum": ">=", "maximum": "<=", "exclusiveMinimum": ">", "exclusiveMaximum": "<"}
    if v in bounds:
        return [(path, f"must be {bounds[v]} {val}; got {preview(inst)}")]
    if v in ("minItems", "maxItems"):
        return [(path, f"has {len(inst)} item{'s' if len(inst) != 1 else ''}; needs "
                       f"{'at least' if v == 'minItems' else 'at most'} {val}")]
    if v == "items" and val is False:
        return [(path, f"has {len(inst)} items; expected {len(err.schema.get('prefixItems', []))}")]
    if v == "pattern":
        like = err.schema.get("examples", [val])[0]
        return [(path, f"must look like {json.dumps(like)} (pattern {val}); got {preview(inst)}")]
    if v == "minLength":
        return [(path, "must not be empty")]
    return [(path, f"{v}: {val!r} does not hold for {preview(inst)}")]


def _article(t):
    return {"object": "an object", "array": "an array", "integer": "an integer", "null": "null"}.get(t, f"a {t}")


# -- hand checks ----------------------------------------------------------
def body_problems(bodies, bad: Rejected, version: int = fmt.VERSION):
    """(problems, shapes): each body's fixtures built (shapes[i]: a list of (shape, fields) pairs,
    or None if they were not), then the mass and inertia each density gives, which must be
    representable.  (Centres of mass cannot overflow: shape coordinates are at most
    shapes.MAX_COORDINATE, far below a float's last ulp.)"""
    out, shapes = [], []
    for i, b in enumerate(bodies):
        path = ("bodies", i)
        shapes.append(None)
        if not isinstance(b, dict):
            continue
        if path in bad:  # something in this body is wrong already: build nothing of it
            continue
        if b.get("awake") is True and "asleep" in b:
            out.append(((*path, "awake"), "true contradicts asleep (the island the body sleeps in); give one"))
        specs, where = _specs(b, path, version, out)
        if not specs:
            continue
        built = [None if p in bad else _build_one(spec, p, version, out) for spec, p in zip(specs, where)]
        if any(x is None for x in built):
            continue
        shapes[i] = [(sh, fields) for made, fields, _ in built for sh in made]
        if b.get("kind", fmt.BODY_DEFAULTS["kind"]) == "dynamic" and all(sh.area == 0.0 for sh, _ in shapes[i]):
            out.append((where[0] if len(where) == 1 else (*path, "shapes"),
                        "a dynamic body needs a shape with area (segments and chains have none); make it "
                        "static or kinematic"))
            continue
        density = b.get("density", fmt.BODY_DEFAULTS["density"])
        for made, fields, p in built:
            d_path = (*p, "density") if "density" in fields else (*path, "density")
            if d_path in bad or d_path in {q for q, _ in out}:
                continue
            try:
                for sh in made:
                    checked_density(fields.get("density", density), sh)
            except ValueError as exc:
                out.append((d_path, str(exc).removeprefix("density: ")))
    return out, shapes


def _specs(b, path, version, out):
    """(shape objects, their paths) of a body, or (None, []) with the problem noted."""
    has_one, has_many = "shape" in b, "shapes" in b
    if has_one and has_many:
        out.append(((*path, "shapes"), "give shape or shapes, not both"))
        return None, []
    if not has_one and not has_many:
        out.append(((*path, "shape"), "required field is missing"))
        return None, []
    if has_many:
        if version < 2:
            out.append(((*path, "shapes"), "shapes (several per body) need a version 2 scene"))
            return None, []
        specs = b["shapes"] if isinstance(b["shapes"], list) else []
        return specs, [(*path, "shapes", k) for k in range(len(specs))]
    return [b["shape"]], [(*path, "shape")]


def _build_one(spec, path, version, out):
    """(shapes, fixture fields, path) of one shape object, or None with the problem noted."""
    if not isinstance(spec, dict):
        return None
    key, reason = shape_problem(spec, version) or (None, None)
    if reason is not None:
        out.append(((*path, key) if key else path, reason))
        return None
    kind = kind_of(spec)
    try:
        return make_shapes(spec), fixture_fields(spec), path
    except ValueError as exc:
        out.append(((*path, kind), str(exc)))
        return None


def name_problems(items, what: str, section: str, bad: Rejected) -> list:
    out, first = [], {}
    for i, item in enumerate(items):
        name = item.get("name") if isinstance(item, dict) else None
        if not isinstance(name, str) or (section, i, "name") in bad:
            continue
        if name in first:
            out.append(((section, i, "name"),
                        f"duplicate {what} name {quoted(name)} (first used by {section}[{first[name]}])"))
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
                out.append((("springs", i, end), f"no body named {quoted(ref)}"))
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
        return [(("world", "solver"), f"unknown solver {quoted(name)}; this build has: {', '.join(solvers.available())}")]
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
            out.append((path, f"solver {name!r} has no setting {quoted(key)}; it has: {', '.join(mode.settings)}"))
            continue
        try:
            mode.settings[key].coerce(value)
        except ValueError as exc:
            out.append((path, str(exc)))
    return out


def hand_problems(data, bad: Rejected):
    """(problems, shapes) for the checks a schema cannot express: the cheap ones (names, links,
    the solver) first, then the shapes of each body nothing was found wrong with (building one
    can mean decomposing a 10,000-vertex outline: never for a body that is refused anyway)."""
    bodies = data.get("bodies") if isinstance(data.get("bodies"), list) else []
    springs = data.get("springs") if isinstance(data.get("springs"), list) else []
    joints = data.get("joints") if isinstance(data.get("joints"), list) else []
    world = data.get("world") if isinstance(data.get("world"), dict) else {}
    version = data.get("version", fmt.VERSION)
    out = name_problems(bodies, "body", "bodies", bad)
    out += name_problems(springs, "spring", "springs", bad)
    out += spring_problems(bodies, springs, bad)
    out += name_problems(joints, "joint", "joints", bad)
    out += joint_problems(bodies, joints, bad)
    out += solver_problems(world, bad)
    out += sandbox_problems(bodies, data.get("sandbox"), bad)
    more, shapes = body_problems(bodies, Rejected([*bad.paths, *(p for p, _ in out)]),
                                 version if version in fmt.VERSIONS else fmt.VERSION)
    return out + more, shapes


def check(data):
    """(problems, shapes) for scene data; problems are (json_path_string, reason) in document order,
    at most schema.MAX_PROBLEMS + 1 of them."""
    problems = header_problems(data)
    if problems:
        return finish(problems), []
    too_many = count_problem(data) or work_problem(data)
    if too_many:  # before any value is walked: the counts alone can ask for minutes of work
        return finish([too_many]), []
    problems, stop = value_problems(data)
    if stop:
        return finish(problems), []  # the schema and hand checks recurse; never give them deep or huge data
    problems += schema_problems(data, Rejected(p for p, _ in problems))
    more, shapes = hand_problems(data, Rejected(p for p, _ in problems))
    return finish(problems + more), shapes
