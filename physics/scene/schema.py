"""The scene format as a JSON Schema (draft 2020-12), with every default.

This module is the source of truth: the published ``scenes/stelkropp.schema.json``
is its ``schema_text()``, written by ``scenes/make_scenes.py --schema`` (and printed
by ``python -m physics schema``; a test keeps the two byte-for-byte equal), so an installed package validates without the repository's files.
The schema checks structure, types and ranges; what it cannot express
(convexity, names that refer to each other, the solver's own settings) is
checked by hand in ``physics/scene/checks.py``.
"""
from __future__ import annotations

import json

from .. import options
from ..store import KINDS as _KIND_CODES
from .joints import JOINT_SCHEMA
from .shapes import shape_schema

FORMAT = "stelkropp.scene"
#: the version written; every version in VERSIONS is read (1: one shape per body)
VERSION = 2
VERSIONS = (1, 2)
SCHEMA_FILE = "stelkropp.schema.json"

# refuse before parsing / before validating, so a hostile file cannot eat the machine
MAX_FILE_BYTES = 50 * 1024 * 1024
MAX_BODIES = 1_000_000
# the format nests 7 deep (bodies[i].shapes[j].polygon[k][l]); deeper data is refused before the schema
MAX_DEPTH = 32
# no legal scene comes near these (the work limit, budget.py, allows about a million values):
# refused while the values are walked, so a 50 MB file of one list is not walked to its end
MAX_VALUES = 1_500_000
MAX_ITEMS = 1_000_000
# a SceneError lists at most this many problems (a hostile file can have millions)
MAX_PROBLEMS = 100

# the World's own choices, from the one list of names (physics/options.py)
SOLVERS = list(options.SOLVERS)
INTEGRATORS = list(options.INTEGRATORS)
BROADPHASES = list(options.BROADPHASES)
NARROWPHASES = list(options.NARROWPHASES)
KINDS = list(_KIND_CODES)

WORLD_DEFAULTS = {
    "gravity": [0.0, -9.81],
    "dt": 1.0 / 60.0,
    "solver": options.DEFAULT_SOLVER,
    "settings": {},
    "integrator": options.DEFAULT_INTEGRATOR,
    "sleeping": True,
    "broadphase": options.DEFAULT_BROADPHASE,
    "narrowphase": options.DEFAULT_NARROWPHASE,
}
BODY_DEFAULTS = {
    "name": None,
    "kind": "dynamic",
    "angle": 0.0,
    "velocity": [0.0, 0.0],
    "angular_velocity": 0.0,
    "density": 1.0,
    "restitution": 0.0,
    "friction": 0.6,
}
#: a body's optional sandbox colour: "#rrggbb"
COLOR_PATTERN = "^#[0-9a-fA-F]{6}$"
# rest_length None: the distance between the anchors when the scene is built
SPRING_DEFAULTS = {
    "name": None,
    "anchor_a": [0.0, 0.0],
    "anchor_b": [0.0, 0.0],
    "damping": 0.0,
    "rest_length": None,
}


def _num(doc, **kw):
    return {"type": "number", "description": doc, **kw}


def _vec(doc, **kw):
    return {"type": "array", "description": doc, "prefixItems": [{"type": "number"}, {"type": "number"}],
            "items": False, "minItems": 2, **kw}


def _name(doc):
    return {"type": "string", "minLength": 1, "description": doc}


_FRICTION = {
    "type": ["number", "object"],
    "description": "Coulomb coefficient: one number (static = dynamic) or {static, dynamic}",
    "default": BODY_DEFAULTS["friction"],
    # minimum applies to numbers only, properties to objects only: no oneOf, so errors stay specific
    "minimum": 0,
    "required": ["static", "dynamic"],
    "additionalProperties": False,
    "properties": {"static": _num("static coefficient", minimum=0), "dynamic": _num("dynamic coefficient", minimum=0)},
}

_SHAPE = shape_schema(_vec, _num, "#/$defs/friction")

_BODY = {
    "type": "object",
    "description": "A rigid body: one shape, or (version 2) a list of shapes, each a fixture",
    "required": ["position"],
    "additionalProperties": False,
    "properties": {
        "name": _name("unique body name (springs refer to bodies by name); optional"),
        "kind": {"enum": KINDS, "default": BODY_DEFAULTS["kind"],
                 "description": "dynamic, static (never moves) or kinematic (moves with its velocity only)"},
        "shape": {"$ref": "#/$defs/shape"},
        "shapes": {"type": "array", "minItems": 1, "items": {"$ref": "#/$defs/shape"},
                   "description": "the body's shapes (version 2; instead of shape)"},
        "position": _vec("body origin in world coordinates (m)"),
        "center_of_mass": _vec("world position of the centre of mass (m), to the bit; written only when no "
                               "position maps to it exactly (a moved body's centre can lie off that grid); "
                               "when given it is used, position gives the frame only"),
        "angle": _num("rotation about the body origin (rad, counter-clockwise)", default=0.0),
        "velocity": _vec("velocity of the centre of mass (m/s); ignored for static bodies", default=[0.0, 0.0]),
        "angular_velocity": _num("rad/s, counter-clockwise; ignored for static bodies", default=0.0),
        "density": _num("kg/m^2", exclusiveMinimum=0, default=BODY_DEFAULTS["density"]),
        "restitution": _num("bounciness 0..1 (contacts take the larger of the two)", minimum=0, maximum=1,
                            default=BODY_DEFAULTS["restitution"]),
        "friction": {"$ref": "#/$defs/friction"},
        "asleep": {"type": "integer", "minimum": 0, "maximum": 2 ** 62,
                   "description": "a sleeping body: the number of its island (bodies with one number sleep and "
                                  "wake together; dynamic bodies only); absent: awake.  A sleeping body is at "
                                  "rest: its velocity is not used"},
        "awake": {"type": "boolean", "default": True,
                  "description": "false: the body starts asleep, at rest, in an island of its own (Box2D's "
                                 "isAwake = false; dynamic bodies only, and only while the world's sleeping is "
                                 "on); touching bodies wake it.  asleep, when given, names its island instead"},
        "sleep_time": _num("time (s) the body has stayed below the sleep thresholds", minimum=0, default=0.0),
        "color": {"type": "string", "pattern": COLOR_PATTERN, "examples": ["#e07a5f"],
                  "description": "fill colour in the sandbox, \"#rrggbb\" (ignored by the physics); "
                                 "optional: a palette colour otherwise"},
    },
}

_SPRING = {
    "type": "object",
    "required": ["a", "b", "stiffness"],
    "additionalProperties": False,
    "properties": {
        "name": _name("unique spring name; optional"),
        "a": _name("name of the first body"),
        "b": {"type": ["string", "null"], "minLength": 1,
              "description": "name of the second body, or null: anchor_b is then a world point"},
        "anchor_a": _vec("attachment on a, in a's body coordinates (m)", default=[0.0, 0.0]),
        "anchor_b": _vec("attachment on b (b's body coordinates), or the world point when b is null",
                         default=[0.0, 0.0]),
        "stiffness": _num("N/m", minimum=0),
        "damping": _num("N s/m along the spring axis", minimum=0, default=0.0),
        "rest_length": _num("m; default: the distance between the anchors when the scene is built", minimum=0),
    },
}

_WORLD = {
    "type": "object",
    "additionalProperties": False,
    "properties": {
        "gravity": _vec("m/s^2", default=WORLD_DEFAULTS["gravity"]),
        # maximum: physics.world.DT_MAX (a test keeps the two equal; the schema imports no world)
        "dt": _num("time step (s), at most an hour", exclusiveMinimum=0, maximum=3600.0,
                   default=WORLD_DEFAULTS["dt"]),
        "solver": {"type": "string", "default": WORLD_DEFAULTS["solver"],
                   "description": f"solver mode: {', '.join(SOLVERS)} "
                                  "(checked against the modes this build has)"},
        "settings": {"type": "object", "default": {},
                     "description": "the chosen solver's parameters (names, ranges and defaults are declared by "
                                    "each mode; `python -m physics info` lists them); omitted ones take the "
                                    "mode's defaults",
                     "additionalProperties": {"type": ["number", "boolean", "string"]}},
        "integrator": {"enum": INTEGRATORS, "default": WORLD_DEFAULTS["integrator"],
                       "description": "used by the modes that integrate forces explicitly"},
        "sleeping": {"type": "boolean", "default": True, "description": "resting islands sleep"},
        "broadphase": {"enum": BROADPHASES, "default": WORLD_DEFAULTS["broadphase"], "description": "auto picks by body count"},
        "narrowphase": {"enum": NARROWPHASES, "default": WORLD_DEFAULTS["narrowphase"], "description": "polygon-polygon test"},
        "time": _num("simulated time (s) when the scene was saved", minimum=0, default=0.0),
        "steps": {"type": "integer", "minimum": 0, "maximum": 2 ** 62, "default": 0,
                  "description": "steps taken when the scene was saved"},
    },
}

_CAMERA = {
    "type": "object",
    "description": "Where the sandbox looks when it opens the scene (ignored by the physics)",
    "additionalProperties": False,
    "properties": {
        "center": _vec("world point at the middle of the view (m)"),
        "zoom": _num("pixels per metre", exclusiveMinimum=0),
    },
}

_SANDBOX_POINT = {"type": "array", "prefixItems": [{"type": "number"}, {"type": "number"}], "items": False,
          "minItems": 2, "description": "[x, y] (m): in the body's frame, or the world's without a body"}

#: the sandbox's lasers and tracers (app data; physics/scene/sandbox.py loads and saves them)
SANDBOX = {
    "type": "object",
    "description": "The sandbox's lasers and tracers (ignored by the physics)",
    "additionalProperties": False,
    "properties": {
        "lasers": {"type": "array", "default": [], "items": {
            "type": "object", "additionalProperties": False, "required": ["point"],
            "properties": {"body": {"type": ["string", "null"], "minLength": 1, "default": None,
                                    "description": "name of the body it rides on; null: fixed in the world"},
                           "point": _SANDBOX_POINT,
                           "angle": {"type": "number", "default": 0.0,
                                     "description": "beam direction (rad) in the body's frame or the world's"}}}},
        "tracers": {"type": "array", "default": [], "items": {
            "type": "object", "additionalProperties": False, "required": ["body", "point"],
            "properties": {"body": {"type": "string", "minLength": 1, "description": "name of the traced body"},
                           "point": _SANDBOX_POINT}}},
    },
}


SCHEMA = {
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "title": "Stelkropp scene",
    "description": "A 2D rigid-body scene for Stelkropp.  Units: metres, kilograms, seconds, radians.",
    "type": "object",
    "required": ["format", "version", "bodies"],
    "additionalProperties": False,
    "properties": {
        "$schema": {"type": "string", "description": "path or URL of this schema (for editors)"},
        "format": {"const": FORMAT},
        "version": {"enum": list(VERSIONS)},
        "name": {"type": "string", "description": "title shown in the sandbox"},
        "description": {"type": "string", "description": "what the scene demonstrates"},
        "world": {"$ref": "#/$defs/world"},
        "camera": {"$ref": "#/$defs/camera"},
        "bodies": {"type": "array", "items": {"$ref": "#/$defs/body"}},
        "springs": {"type": "array", "default": [], "items": {"$ref": "#/$defs/spring"}},
        "joints": {"type": "array", "default": [], "items": {"$ref": "#/$defs/joint"}},
        "sandbox": {"$ref": "#/$defs/sandbox"},
    },
    "$defs": {
        "vec2": _vec("[x, y]"),
        "shape": _SHAPE,
        "friction": _FRICTION,
        "body": _BODY,
        "spring": _SPRING,
        "joint": JOINT_SCHEMA,
        "world": _WORLD,
        "camera": _CAMERA,
        "sandbox": SANDBOX,
    },
}


def schema_text() -> str:
    """The published schema file's exact text (``scenes/stelkropp.schema.json``)."""
    return json.dumps(SCHEMA, indent=2) + "\n"

