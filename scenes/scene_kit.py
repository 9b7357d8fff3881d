"""Building blocks of the shipped scenes (scenes/make_scenes.py, scenes/joint_scenes.py).

Every helper returns plain scene-file data (dicts and lists, the format of
docs/scene-format.md), rounded to micrometres so the files stay readable.
"""
from __future__ import annotations

import math

DT = 1.0 / 60.0
G = [0.0, -10.0]


def r(x, digits=6):
    """Round to micrometres: the files stay readable and nothing here needs more."""
    return round(float(x), digits) + 0.0  # + 0.0 turns -0.0 into 0.0


def pt(p):
    """A point or vector as a rounded list."""
    return [r(p[0]), r(p[1])]


def scene(name, description, bodies, springs=(), camera=None, joints=(), **world):
    """A whole scene: world block (g = 10 m/s^2 down, dt 1/60 s, soft_step) and its contents."""
    out = {"format": "stelkropp.scene", "version": 2, "name": name, "description": description,
           "world": {"gravity": G, "dt": DT, "solver": "soft_step", "settings": {},
                     "integrator": "symplectic_euler", "sleeping": True, **world},
           "camera": camera or {"center": [0.0, 5.0], "zoom": 30.0},
           "bodies": list(bodies), "springs": list(springs)}
    if joints:
        out["joints"] = list(joints)
    return out


def body(shape, x, y, name=None, **kw):
    b = {"shape": shape, "position": [r(x), r(y)], **kw}
    if name:
        b = {"name": name, **b}
    return b


def static(shape, x, y, name=None, **kw):
    return body(shape, x, y, name, kind="static", **kw)


def box(w, h):
    return {"box": [r(w), r(h)]}


def poly(points):
    return {"polygon": [[r(x), r(y)] for x, y in points]}


def circle(radius):
    return {"circle": r(radius)}


def spring(a, b, anchor_a, anchor_b, k, c=0.0, rest=None, name=None):
    s = {"a": a, "b": b, "anchor_a": [r(v) for v in anchor_a], "anchor_b": [r(v) for v in anchor_b],
         "stiffness": k, "damping": c}
    if rest is not None:
        s["rest_length"] = r(rest)
    if name:
        s = {"name": name, **s}
    return s


def joint(kind, a, b, name=None, **kw):
    """A joint entry: World.add_joint's keywords for ``kind`` (points and axes in world
    coordinates at creation; the canonical file stores them in body coordinates)."""
    j = {"kind": kind, "a": a, "b": b}
    if name:
        j["name"] = name
    for k, v in kw.items():
        j[k] = pt(v) if isinstance(v, (tuple, list)) else v
    return j


def hinge(a, b, anchor, name=None, **kw):
    return joint("revolute", a, b, name, anchor=anchor, **kw)


def ground(width=40.0, name="ground", y=0.0, friction=0.6):
    return static(box(width, 1.0), 0.0, y - 0.5, name, friction=friction)


def rotate(p, q):
    c, s = math.cos(q), math.sin(q)
    return (c * p[0] - s * p[1], s * p[0] + c * p[1])
