"""Shapes in scene files (format version 2): the schema of a shape object, shapes from it,
its fixture fields, and a body's fixtures back to shape objects.

A shape object holds exactly one kind key (box, polygon, regular, circle, capsule, segment,
chain, concave), an optional ``radius`` that rounds a box, polygon or regular polygon, and
optionally its fixture's own material and filter (``density``, ``friction``,
``restitution``, ``category``, ``mask``, ``group``, ``name``; else the body's; ``sensor``).  A body has
``"shape": {...}`` or ``"shapes": [{...}, ...]``.  A ``concave`` outline is decomposed on
load (physics.decompose) and saved as the outline; a chain is saved as its points.
"""
from __future__ import annotations

from ..fixture import filter_bits, filter_group
from ..geometry.capsule import Capsule, Segment
from ..geometry.chain import Chain, ChainSegment
from ..geometry.decompose import decompose
from ..geometry.shapes import Circle, Polygon
from ..store.fixtures import ALL_BITS, DEFAULT_CATEGORY, DEFAULT_GROUP
from ..validate import flag

KINDS_V1 = ("box", "polygon", "regular", "circle")
KINDS = KINDS_V1 + ("capsule", "segment", "chain", "concave")
ROUNDED = ("box", "polygon", "regular")
MATERIAL = ("density", "friction", "restitution")
FILTER_DEFAULTS = {"category": DEFAULT_CATEGORY, "mask": ALL_BITS, "group": DEFAULT_GROUP}
FIXTURE_KEYS = MATERIAL + tuple(FILTER_DEFAULTS) + ("name", "sensor")


def shape_schema(vec, num, friction_ref) -> dict:
    """The JSON Schema of a shape object (``vec``/``num`` build the schema's vectors and numbers)."""
    def pts(doc, **kw):  # "items" last: jsonschema reports in this order, and a count beats a million items
        return {"type": "array", "description": doc, **kw, "items": {"$ref": "#/$defs/vec2"}}
    bits = {"type": "integer", "minimum": 0, "maximum": ALL_BITS}
    return {
        "type": "object",
        "description": f"Exactly one of {', '.join(KINDS)}, plus optional radius (box, polygon, regular) and "
                       "the fixture's own material and filter.  Vertices are in body coordinates (metres).",
        "additionalProperties": False,
        "properties": {
            "box": vec("[width, height] of a box centred on the body origin",
                       prefixItems=[{"type": "number", "exclusiveMinimum": 0}] * 2),
            "polygon": pts("convex polygon vertices [[x, y], ...], either winding, 3..64", minItems=3, maxItems=64),
            "regular": {"type": "object", "description": "regular polygon with a flat bottom edge",
                        "required": ["sides", "radius"], "additionalProperties": False,
                        "properties": {"sides": {"type": "integer", "minimum": 3, "maximum": 64},
                                       "radius": num("circumradius (m)", exclusiveMinimum=0)}},
            "circle": {"type": ["number", "object"],
                       "description": "radius (m), or {radius, offset} for a disc off the body origin",
                       "exclusiveMinimum": 0, "required": ["radius"], "additionalProperties": False,
                       "properties": {"radius": num("radius (m)", exclusiveMinimum=0),
                                      "offset": vec("centre in body coordinates", default=[0.0, 0.0])}},
            "capsule": {"type": "object", "description": "points within radius of the segment a-b (version 2)",
                        "required": ["a", "b", "radius"], "additionalProperties": False,
                        "properties": {"a": vec("first end centre"), "b": vec("second end centre"),
                                       "radius": num("radius (m)", exclusiveMinimum=0)}},
            "segment": pts("[[x, y], [x, y]]: a line segment, no area (static and kinematic bodies; version 2)",
                           minItems=2, maxItems=2),
            "chain": {"type": "object", "description": "one-sided smooth polyline: solid to the left of the "
                                                      "direction from point to point (version 2)",
                      "required": ["points"], "additionalProperties": False,
                      "properties": {"points": pts("the chain's points", minItems=2, maxItems=100_000),
                                     "loop": {"type": "boolean", "default": False}}},
            "concave": pts("simple polygon outline, decomposed into convex pieces on load (version 2)",
                           minItems=3, maxItems=10_000),
            "radius": num("rounding of a box, polygon or regular polygon (m; version 2)", minimum=0, default=0.0),
            "density": num("this fixture's kg/m^2 (default: the body's)", exclusiveMinimum=0),
            "restitution": num("this fixture's bounciness 0..1 (default: the body's)", minimum=0, maximum=1),
            "friction": {"$ref": friction_ref},
            "category": {**bits, "description": "filter bits this fixture is (default 1)"},
            "mask": {**bits, "description": "filter bits it collides with (default all)"},
            "group": {"type": "integer", "minimum": -2 ** 31, "maximum": 2 ** 31 - 1,
                      "description": "shared positive group: always collide; negative: never (default 0)"},
            "name": {"type": "string", "minLength": 1, "description": "fixture name (need not be unique)"},
            "sensor": {"type": "boolean", "default": False,
                       "description": "a sensor: no mass, no contact; reports the fixtures it overlaps (version 2)"},
        },
    }


def kind_of(spec: dict):
    """The one kind key of a shape object, or None if it has none or several."""
    keys = [k for k in spec if k in KINDS]
    return keys[0] if len(keys) == 1 else None


def make_shapes(spec: dict) -> list:
    """The fixture shapes of a (schema-valid) shape object; ValueError if the geometry is bad."""
    key = kind_of(spec)
    val = spec[key]
    r = spec.get("radius", 0.0)
    if key == "box":
        return [Polygon.box(*val, radius=r)]
    if key == "polygon":
        return [Polygon(val, r)]
    if key == "regular":
        return [Polygon.regular(val["sides"], val["radius"], r)]
    if key == "circle":
        return [Circle(val["radius"], val.get("offset", (0.0, 0.0))) if isinstance(val, dict) else Circle(val)]
    if key == "capsule":
        return [Capsule(val["a"], val["b"], val["radius"])]
    if key == "segment":
        return [Segment(*val)]
    if key == "chain":
        return list(Chain(val["points"], val.get("loop", False)).segments)
    return decompose(val)


def shape_problem(spec: dict, version: int):
    """(key, reason) for what the schema cannot say about a shape object, or None."""
    key = kind_of(spec)
    if key is None:
        return None, f"give exactly one of {', '.join(KINDS)}"
    if "radius" in spec and key not in ROUNDED:
        return "radius", f"radius rounds a box, polygon or regular polygon; a {key} has none here"
    if version < 2:
        extra = [k for k in spec if k != key]
        if key not in KINDS_V1:
            return key, f"{key} shapes need a version 2 scene"
        if extra:
            return extra[0], f"{extra[0]} in a shape needs a version 2 scene"
    return None


def fixture_fields(spec: dict) -> dict:
    """The fixture's own fields a shape object gives (validated like the setters)."""
    out = {k: spec[k] for k in FIXTURE_KEYS if k in spec}
    for k in ("category", "mask"):
        if k in out:
            out[k] = filter_bits(out[k], k)
    if "group" in out:
        out["group"] = filter_group(out["group"])
    if "sensor" in out:
        out["sensor"] = flag(out["sensor"], "sensor")
    return out


# -- saving ---------------------------------------------------------------
def _fields(fx, first, same) -> dict:
    """The fields of fixture ``fx`` that differ from what the body gives (its first fixture's material)."""
    out = {}
    if not same(fx.density, first.density):
        out["density"] = fx.density
    if not same(fx.friction, first.friction):
        mu_s, mu_d = fx.friction
        out["friction"] = mu_s if mu_s == mu_d else {"static": mu_s, "dynamic": mu_d}
    if not same(fx.restitution, first.restitution):
        out["restitution"] = fx.restitution
    for k, default in FILTER_DEFAULTS.items():
        if getattr(fx, k) != default:
            out[k] = getattr(fx, k)
    if fx.name is not None:
        out["name"] = fx.name
    if fx.sensor:
        out["sensor"] = True
    return out


def _source(shape):
    """What a fixture's shape is a part of (a chain, a decomposed outline) or None."""
    if isinstance(shape, ChainSegment):
        return shape.chain
    return getattr(shape, "outline", None)


def shape_objects(body, same) -> list:
    """A body's fixtures as shape objects: runs of pieces of one outline or one chain with equal
    fields become one ``concave`` or ``chain`` object."""
    fixtures = body.fixtures
    first = fixtures[0]
    out, k = [], 0
    while k < len(fixtures):
        fx = fixtures[k]
        fields = _fields(fx, first, same)
        src = _source(fx.shape)
        end = k + 1
        if src is not None:
            while end < len(fixtures) and _source(fixtures[end].shape) is src \
                    and _fields(fixtures[end], first, same) == fields:
                end += 1
        if isinstance(src, Chain) and end - k != len(src.segments):  # part of a chain: its segments
            end = k + 1
            spec = {"segment": fx.shape.vertices.tolist()}
        elif isinstance(src, Chain):
            spec = src.spec
        elif src is not None:
            spec = {"concave": src.tolist()}
        else:
            spec = dict(fx.shape.spec)
        out.append({**spec, **fields})
        k = end
    return out
