"""A World as scene data that reloads to the identical world.

The world stores centres of mass; files store body origins.  Converting
back (origin = x - R com) can land one ulp off, and the reloaded world would
then differ in the last bit.  So every converted coordinate is chosen to
reproduce the stored value exactly under the loader's arithmetic, preferring
the shortest decimal that does (files stay readable: 0.5, not
0.49999999999999994).  Fields equal to their documented default are left out.
"""
from __future__ import annotations

import json
import math

from ..store import DYNAMIC, KIND_NAMES
from . import schema as fmt
from .joints import joint_dict
from .sandbox import sandbox_bodies, sandbox_dict
from .shapes import shape_objects


def _shortest(target: float, base: float, forward) -> float:
    """A float p with forward(p) == target exactly, as short in decimal as possible."""
    for digits in range(0, 18):
        p = round(base, digits)
        if forward(p) == target:
            return p
    p = base
    for _ in range(8):  # a few ulps either side of the naive inverse
        for q in (p, math.nextafter(p, math.inf), math.nextafter(p, -math.inf)):
            if forward(q) == target:
                return q
        p = math.nextafter(p, math.inf if forward(p) < target else -math.inf)
    return _bisect(target, base, forward)


def _bisect(target: float, base: float, forward) -> float:
    """The smallest float p near ``base`` with forward(p) == target, for a nondecreasing forward
    (p + t): when p is far finer-grained than the result (a centre of mass of 3e-17 m), a few ulps
    of p move nothing and the answer is many ulps away.  base is off by at most an ulp of the
    larger operand, so a bracket of a few of those holds it."""
    u = math.ulp(max(abs(target), abs(base), abs(target - base))) * 4
    lo, hi = base - u, base + u
    for _ in range(2100):  # each pass halves the bracket; floats have 2^64 values
        if lo >= hi:
            break
        mid = lo + (hi - lo) / 2
        if mid in (lo, hi):
            mid = lo
        if forward(mid) < target:
            lo = math.nextafter(mid, math.inf)
        else:
            hi = mid
    return lo if forward(lo) == target else base


def _origin(x, q, com):
    """Body origin that World.add_body maps back to the centre of mass ``x`` exactly."""
    c, s = math.cos(q), math.sin(q)
    t = (c * com[0] - s * com[1], s * com[0] + c * com[1])
    return [_shortest(float(x[k]), float(x[k]) - t[k], lambda p, k=k: p + t[k]) for k in range(2)]


def _reaches(origin, x, q, com) -> bool:
    """Whether World.add_body maps ``origin`` to the centre of mass ``x`` exactly."""
    c, s = math.cos(q), math.sin(q)
    t = (c * com[0] - s * com[1], s * com[0] + c * com[1])
    return all(origin[k] + t[k] == float(x[k]) for k in range(2))


def _anchor(local, com):
    """Anchor in body coordinates that World.add_spring maps back to ``local`` (relative to com)."""
    return [_shortest(float(local[k]), float(local[k]) + float(com[k]), lambda p, k=k: p - float(com[k]))
            for k in range(2)]


def _same(a, b) -> bool:
    """Equal as JSON text: distinguishes -0.0 from 0.0 (unlike ==) and 1 from 1.0.  Floats and
    pairs of them (every fixture of a 100,000-point chain asks) take the fast path."""
    if type(a) is float and type(b) is float:
        return a == b and math.copysign(1.0, a) == math.copysign(1.0, b)
    if type(a) is tuple and type(b) is tuple and len(a) == len(b):
        return all(_same(x, y) for x, y in zip(a, b))
    return json.dumps(a) == json.dumps(b)


def _put(out: dict, key, value, default):
    if not _same(value, default):
        out[key] = value


def _vec(v):
    return [float(v[0]), float(v[1])]


def body_dict(world, body, name, color=None) -> dict:
    B = world._bodies.view
    s = body._s
    out = {"name": name} if name is not None else {}
    _put(out, "kind", KIND_NAMES[int(B.kind[s])], fmt.BODY_DEFAULTS["kind"])
    specs = shape_objects(body, _same)
    if len(specs) == 1:
        out["shape"] = specs[0]
    else:
        out["shapes"] = specs
    out["position"] = _origin(B.x[s], float(B.q[s]), B.com[s])
    if not _reaches(out["position"], B.x[s], float(B.q[s]), B.com[s]):
        # no origin maps to this centre exactly (the step moved it off the grid origin + R com
        # can reach): the centre itself, which the loader then takes to the bit
        out["center_of_mass"] = _vec(B.x[s])
    _put(out, "angle", float(B.q[s]), fmt.BODY_DEFAULTS["angle"])
    _put(out, "velocity", _vec(B.v[s]), fmt.BODY_DEFAULTS["velocity"])
    _put(out, "angular_velocity", float(B.w[s]), fmt.BODY_DEFAULTS["angular_velocity"])
    _put(out, "density", float(B.density[s]), fmt.BODY_DEFAULTS["density"])
    _put(out, "restitution", float(B.e[s]), fmt.BODY_DEFAULTS["restitution"])
    mu_s, mu_d = float(B.mu_s[s]), float(B.mu_d[s])
    _put(out, "friction", mu_s if mu_s == mu_d else {"static": mu_s, "dynamic": mu_d}, fmt.BODY_DEFAULTS["friction"])
    if B.kind[s] == DYNAMIC and not B.awake[s]:
        out["asleep"] = int(B.island[s])
    _put(out, "sleep_time", float(B.sleep_t[s]), 0.0)
    if color is not None:
        out["color"] = color
    return out


def spring_dict(world, sp, names) -> dict:
    S = world._springs.view
    B = world._bodies.view
    s = sp._s
    out = {"name": sp.name} if sp.name is not None else {}
    out["a"] = names[sp.body_a.id]
    out["b"] = None if sp.body_b is None else names[sp.body_b.id]
    out["anchor_a"] = _anchor(S.la[s], B.com[sp.body_a._s])
    out["anchor_b"] = _vec(S.lb[s]) if sp.body_b is None else _anchor(S.lb[s], B.com[sp.body_b._s])
    out["stiffness"] = float(S.k[s])
    _put(out, "damping", float(S.c[s]), fmt.SPRING_DEFAULTS["damping"])
    out["rest_length"] = float(S.rest[s])  # always: the default depends on where the bodies are
    return out


def body_names(world, also=()) -> dict:
    """id -> name; bodies that springs or joints (or the ids in ``also``) refer to but that have
    no name get a free ``bodyN``, N the body's id (the sandbox shows an unnamed body by its id:
    the saved name must be what the user saw)."""
    names = {b.id: b.name for b in world.bodies}
    taken = {n for n in names.values() if n is not None}
    links = list(world.springs) + list(world.joints)
    needed = {x.body_a.id for x in links} | {x.body_b.id for x in links if x.body_b is not None} | set(also)
    for b in world.bodies:
        if names[b.id] is None and b.id in needed:
            name, k = f"body{b.id}", 0
            while name in taken:
                k += 1
                name = f"body{b.id}_{k}"
            names[b.id] = name
            taken.add(name)
    return names


def world_dict(world) -> dict:
    settings = world.settings.assigned()  # a value the world chose from the scene is chosen again on loading
    out = {"gravity": list(world.gravity), "dt": world.dt, "solver": world.solver, "settings": settings,
           "integrator": world.integrator, "sleeping": world.sleeping}
    _put(out, "broadphase", world.broadphase, fmt.WORLD_DEFAULTS["broadphase"])
    _put(out, "narrowphase", world.narrowphase, fmt.WORLD_DEFAULTS["narrowphase"])
    _put(out, "time", float(world.time), 0.0)
    if world.steps:
        out["steps"] = int(world.steps)
    return out


def to_dict(world, meta: dict) -> dict:
    out = {"$schema": fmt.SCHEMA_FILE, "format": fmt.FORMAT, "version": fmt.VERSION}
    for key in ("name", "description"):
        if meta.get(key) is not None:
            out[key] = meta[key]
    out["world"] = world_dict(world)
    if meta.get("camera"):
        out["camera"] = meta["camera"]
    names = body_names(world, sandbox_bodies(meta))
    colors = meta.get("colors") or {}     # body id -> "#rrggbb" (the sandbox's, see load._build)
    out["bodies"] = [body_dict(world, b, names[b.id], colors.get(b.id)) for b in world.bodies]
    out["springs"] = [spring_dict(world, sp, names) for sp in world.springs]
    if world.joints:
        out["joints"] = [joint_dict(world, j, names, _anchor, _same) for j in world.joints]
    sandbox = sandbox_dict(meta, names)
    if sandbox:
        out["sandbox"] = sandbox
    return out
