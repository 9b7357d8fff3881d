"""A bench scene description (a Stelkropp scene dict) as Box2D v3 command records.

What is read (see docs/scene-format.md and issues 13/14 for the keys of both engines):

* ``world``: ``gravity``, ``dt``, ``sleeping``, ``settings.substeps``; Box2D-only tuning under
  ``world.box2d``: ``contact_hertz``, ``contact_damping_ratio``, ``contact_speed``,
  ``restitution_threshold``, ``max_linear_speed``, ``continuous``, ``contact_softening``,
  ``hit_event_threshold`` (defaults: Box2D's).
* each body: ``kind``, ``position`` (origin), ``angle``, ``velocity`` (of the centre of mass),
  ``angular_velocity``, ``shape`` or ``shapes`` with per-shape materials and filters, body-level
  ``density`` / ``friction`` / ``restitution``, ``awake`` (false: created asleep; ``box2d.awake``
  overrides it); Box2D-only under ``body.box2d``: ``bullet``,
  ``enable_sleep``, ``awake``, ``allow_fast_rotation``, ``gravity_scale``, ``linear_damping``,
  ``angular_damping``, ``sleep_threshold``.
* ``joints`` (``joints.py``) and version-1 ``springs``.
Stelkropp ignores every ``box2d`` key; ``bench.suite.common.strip_box2d`` removes them.
"""
from __future__ import annotations

import math

from .joints import joint_record, spring_record
from .lib import OP_BODY, OP_VELOCITY, WORLD_PARAMS
from .shapes import body_shapes, has_area, shape_records

BODY_TYPES = {"static": 0, "kinematic": 1, "dynamic": 2}


def _vec(v, path, default=(0.0, 0.0)):
    if v is None:
        return default
    if not (isinstance(v, (list, tuple)) and len(v) == 2):
        raise ValueError(f"{path}: expected [x, y]")
    x, y = float(v[0]), float(v[1])
    if not (math.isfinite(x) and math.isfinite(y)):
        raise ValueError(f"{path}: must be finite")
    return (x, y)


def world_params(desc, sleeping, threads, scheduler, track_angles):
    """The numbers of ``s2_world_create``."""
    from .lib import SCHEDULERS
    w = desc.get("world", {})
    b = w.get("box2d", {})
    g = _vec(w.get("gravity"), "world.gravity", (0.0, -9.81))
    sleep = bool(w.get("sleeping", True)) if sleeping is None else bool(sleeping)
    if scheduler not in SCHEDULERS:
        raise ValueError(f"scheduler must be one of {', '.join(SCHEDULERS)}; got {scheduler!r}")
    p = [g[0], g[1], float(sleep), float(b.get("continuous", True)), float(threads), float(SCHEDULERS[scheduler]),
         b.get("contact_hertz", -1.0), b.get("contact_damping_ratio", -1.0), b.get("contact_speed", -1.0),
         b.get("restitution_threshold", -1.0), b.get("max_linear_speed", -1.0),
         float(b.get("contact_softening", False)), float(track_angles), b.get("hit_event_threshold", -1.0)]
    assert len(p) == WORLD_PARAMS
    return [float(x) for x in p]


def body_records(body, slot, path):
    """(records, pose) for one body: the body, its shapes, then its centre-of-mass velocity."""
    if not isinstance(body, dict):
        raise ValueError(f"{path}: a body is an object")
    kind = body.get("kind", "dynamic")
    if kind not in BODY_TYPES:
        raise ValueError(f"{path}.kind: one of static, kinematic, dynamic; got {kind!r}")
    pos = _vec(body.get("position"), f"{path}.position")
    angle = float(body.get("angle", 0.0))
    vel = _vec(body.get("velocity"), f"{path}.velocity")
    av = float(body.get("angular_velocity", 0.0))
    ext = body.get("box2d", {})
    flags = (1 if ext.get("bullet") else 0) | (0 if ext.get("enable_sleep", True) else 2) \
        | (0 if ext.get("awake", body.get("awake", True)) else 4) | (8 if ext.get("allow_fast_rotation") else 0)
    recs = [[OP_BODY, BODY_TYPES[kind], pos[0], pos[1], angle, 0.0, 0.0, 0.0, float(flags),
             float(ext.get("gravity_scale", 1.0)), float(ext.get("linear_damping", 0.0)),
             float(ext.get("angular_damping", 0.0)), float(ext.get("sleep_threshold", -1.0))]]
    shapes = body_shapes(body, path)
    if kind == "dynamic" and not any(has_area(s) for s, _ in shapes):
        raise ValueError(f"{path}: a dynamic body needs a shape with area (segments and chains have none)")
    for spec, spath in shapes:
        recs.extend(shape_records(slot, spec, body, spath))
    if kind != "static" and (vel != (0.0, 0.0) or av != 0.0):
        recs.append([OP_VELOCITY, slot, vel[0], vel[1], av])
    return recs, (pos, angle)


def bodies_records(bodies, first_slot, names, path="bodies"):
    """Records for a list of bodies created from slot ``first_slot``; fills ``names`` with
    name -> (slot, pose) (an unnamed body is reachable by its slot number, as bench/desc.py does)."""
    if not isinstance(bodies, list):
        raise ValueError(f"{path}: a list of bodies expected")
    out = []
    for i, b in enumerate(bodies):
        slot = first_slot + i
        recs, pose = body_records(b, slot, f"{path}[{i}]")
        out.extend(recs)
        name = b.get("name", slot)
        if name is not None:
            if name in names:
                raise ValueError(f"{path}[{i}].name: duplicate body name {name!r}")
            names[name] = (slot, pose)
    return out


def joints_records(joints, names, path="joints"):
    """(records, kinds) for a list of joint specs."""
    if not isinstance(joints, list):
        raise ValueError(f"{path}: a list of joints expected")
    recs, kinds = [], []
    for i, j in enumerate(joints):
        if not isinstance(j, dict):
            raise ValueError(f"{path}[{i}]: a joint is an object")
        r, k = joint_record(j, names, f"{path}[{i}]")
        recs.append(r)
        kinds.append(k)
    return recs, kinds


def springs_records(springs, names, masses, path="springs"):
    """Records for version-1 springs (soft distance joints)."""
    return [spring_record(s, names, masses, f"{path}[{i}]") for i, s in enumerate(springs)]
