"""A joint as plain data and back: what undo, delete, copy/paste, duplicate and reset keep of it.

``joint_fields(j)`` is ``World.add_joint``'s keywords that rebuild ``j``: its exact body-frame
geometry (local anchors, local axis, reference angle: not world points, so a joint brought back
on a moved body is the same joint) and every parameter of its kind (physics/joint_params.py, the
one table of names).  ``make_joint(world, kind, a, b, fields)`` is the inverse.
"""
from __future__ import annotations

from physics import joint_params as jp

GEOMETRY_FIELDS = ("local_anchor_a", "local_anchor_b", "local_axis", "reference_angle")
COMMON_FIELDS = ("name", "collide_connected", "break_force", "break_torque")


def param_value(j, name):
    """Parameter ``name`` of joint ``j`` as ``add_joint`` takes it (``length`` is the readout of
    the distance now; the parameter is the rest length)."""
    return j.rest_length if name == "length" else getattr(j, name)


def joint_fields(j) -> dict:
    """``add_joint`` keywords (without kind and bodies) that rebuild joint ``j``."""
    geo = jp.GEOMETRY[j.kind]
    out = {f: getattr(j, f) for f in GEOMETRY_FIELDS if f in geo}
    out.update({name: param_value(j, name) for name in jp.PARAMS[j.kind]})
    out.update({f: getattr(j, f) for f in COMMON_FIELDS})
    return out


def moved_world_anchor(kind, fields, offset):
    """``fields`` of a joint held to the world, its world point moved by ``offset`` (a paste or
    duplicate beside the original: the copy hangs from its own point, not the original's)."""
    out = dict(fields)
    if "local_anchor_b" in out:
        p = out["local_anchor_b"]
        out["local_anchor_b"] = (p[0] + offset[0], p[1] + offset[1])
    if kind == "motor":
        p = out["linear_offset"]
        out["linear_offset"] = (p[0] + offset[0], p[1] + offset[1])
    return out


def make_joint(world, kind, body_a, body_b, fields):
    """``world.add_joint`` from ``joint_fields`` (ValueError/TypeError from the core propagate)."""
    return world.add_joint(kind, body_a, body_b, **fields)
