"""The scene format's joints: schema, checks, building and saving (issue 14).

    "joints": [{"kind": "revolute", "name": "hinge", "a": "arm", "b": null, "anchor": [0, 1],
                "lower_angle": -0.5, ...}]

A joint's keys are ``World.add_joint``'s keywords for its kind (physics/joint_params.py:
the kind's parameters, its geometry and name / collide_connected / break_force /
break_torque), so the file and the API cannot drift apart.  Geometry may be given in
world coordinates (``anchor``, ``axis``, ...) or exactly in body coordinates
(``local_anchor_a``, ``local_anchor_b``, ``local_axis``, ``reference_angle``); a saved
joint always stores the exact form, so a round trip is bit for bit.
"""
from __future__ import annotations

from .. import joint_params as jp
from ..store.joints import JOINT_KINDS

_VEC = {"type": "array", "prefixItems": [{"type": "number"}, {"type": "number"}], "items": False, "minItems": 2}
_OPT = {"type": ["number", "null"]}
_RULES = {
    "num": {"type": "number"},
    "nonneg": {"type": "number", "minimum": 0},
    "limit": _OPT,
    "length": {"type": ["number", "null"], "minimum": 0},
    "vec": _VEC,
}
_GEOMETRY_DOC = {
    "anchor": "world point where the bodies are joined at creation (m)",
    "anchor_a": "world point on a at creation (m)",
    "anchor_b": "world point on b at creation (m)",
    "axis": "axis direction in world coordinates at creation",
    "local_anchor_a": "anchor on a in a's body coordinates (m)",
    "local_anchor_b": "anchor on b in b's body coordinates, or the world point when b is null (m)",
    "local_axis": "axis direction in a's body coordinates",
    "reference_angle": "angle of a relative to b at which the joint's angle is 0 (rad)",
}


def _prop(schema, doc, default=None):
    out = {**schema, "description": doc}
    if default is not None:
        out["default"] = list(default) if isinstance(default, tuple) else default
    return out


def _kind_schema(kind) -> dict:
    props = {"kind": {"const": kind}, "a": {}, "b": {}, "name": {}, "collide_connected": {},
             "break_force": {}, "break_torque": {}, "broken": {}}
    for g in jp.GEOMETRY[kind]:
        props[g] = _prop(_VEC if g not in ("reference_angle",) else {"type": "number"}, _GEOMETRY_DOC[g])
    for name, p in jp.PARAMS[kind].items():
        props[name] = _prop(_RULES[p.rule], p.doc, p.default)
    return {"if": {"properties": {"kind": {"const": kind}}, "required": ["kind"]},
            "then": {"properties": props, "additionalProperties": False}}


JOINT_SCHEMA = {
    "type": "object",
    "description": "A joint between body a and body b (null: the world); the keys a kind takes are "
                   "World.add_joint's keywords for it",
    "required": ["kind", "a"],
    "properties": {
        "kind": {"enum": list(JOINT_KINDS), "description": "what the joint holds"},
        "a": {"type": "string", "minLength": 1, "description": "name of the first body"},
        "b": {"type": ["string", "null"], "minLength": 1, "default": None,
              "description": "name of the second body, or null for the world"},
        "name": {"type": "string", "minLength": 1, "description": "unique joint name; optional"},
        "collide_connected": {"type": "boolean", "default": False,
                              "description": "the two bodies still collide with each other"},
        "break_force": {"type": ["number", "null"], "exclusiveMinimum": 0, "default": None,
                        "description": "reaction force (N) at which the joint breaks; null: never"},
        "break_torque": {"type": ["number", "null"], "exclusiveMinimum": 0, "default": None,
                         "description": "reaction torque (N m) at which the joint breaks; null: never"},
        "broken": {"type": "boolean", "default": False,
                   "description": "the joint has broken and holds nothing (saved so it stays broken)"},
    },
    "allOf": [_kind_schema(k) for k in JOINT_KINDS],
}


def joint_problems(bodies, joints, bad) -> list:
    """Dangling or repeated body names and reversed limits, as (path, reason)."""
    names = {b["name"] for b in bodies if isinstance(b, dict) and isinstance(b.get("name"), str)}
    out = []
    for i, jd in enumerate(joints):
        if not isinstance(jd, dict) or ("joints", i) in bad:
            continue
        for end in ("a", "b"):
            ref = jd.get(end)
            if isinstance(ref, str) and ("joints", i, end) not in bad and ref not in names:
                out.append((("joints", i, end), f"no body named {ref!r}"))
        if isinstance(jd.get("a"), str) and jd.get("a") == jd.get("b"):
            out.append((("joints", i, "b"), "a joint needs two different bodies (or null for the world)"))
        kind = jd.get("kind")
        if kind == "mouse" and jd.get("b") is not None:
            out.append((("joints", i, "b"), "a mouse joint pulls a towards a world target: b must be null"))
        if kind in jp.PARAMS:
            try:
                jp.ordered(kind, {k: v for k, v in jd.items() if isinstance(v, (int, float))})
            except ValueError as exc:
                field = str(exc).split(":")[0]
                out.append((("joints", i, field), str(exc).split(": ", 1)[1]))
    return out


def add_joints(world, joints, by_name, scene_error, source) -> None:
    """Build every joint of the (checked) scene data; a refusal names the joint's path."""
    for i, jd in enumerate(joints):
        kw = {k: v for k, v in jd.items() if k not in ("kind", "a", "b", "broken")}
        for k, v in kw.items():
            if isinstance(v, list):
                kw[k] = tuple(v)
        b = jd.get("b")
        try:
            joint = world.add_joint(jd["kind"], by_name[jd["a"]], None if b is None else by_name[b], **kw)
        except (ValueError, TypeError) as exc:
            raise scene_error(source, [(f"joints[{i}]", str(exc))]) from None
        if jd.get("broken"):
            world._break_joint(joint)


def joint_dict(world, j, names, anchor, same) -> dict:
    """One joint as scene data (exact geometry; parameters at their default left out).
    ``anchor(local, com)`` and ``same(a, b)`` are the dump module's exact helpers."""
    J = world._joints.view
    B = world._bodies.view
    s = j._s
    out = {"kind": j.kind}
    if j.name is not None:
        out["name"] = j.name
    out["a"] = names[j.body_a.id]
    out["b"] = None if j.body_b is None else names[j.body_b.id]
    geo = jp.GEOMETRY[j.kind]
    if "local_anchor_a" in geo:
        out["local_anchor_a"] = anchor(J.la[s], B.com[j.body_a._s])
    if "local_anchor_b" in geo:
        lb = J.lb[s]
        out["local_anchor_b"] = ([float(lb[0]), float(lb[1])] if j.body_b is None
                                 else anchor(lb, B.com[j.body_b._s]))
    if "local_axis" in geo:
        out["local_axis"] = [float(J.axis[s, 0]), float(J.axis[s, 1])]
    if "reference_angle" in geo:
        out["reference_angle"] = float(J.ref[s])
    for name, p in jp.PARAMS[j.kind].items():
        v = getattr(j, name) if name != "length" else j.rest_length
        v = list(v) if isinstance(v, tuple) else v
        default = list(p.default) if isinstance(p.default, tuple) else p.default
        if name in ("length", "target") or not same(v, default):
            out[name] = v
    if j.collide_connected:
        out["collide_connected"] = True
    for name in ("break_force", "break_torque"):
        v = getattr(j, name)
        if v is not None:
            out[name] = v
    if j.broken:
        out["broken"] = True
    return out
