"""Scene joints (issue 14's ``"joints": [...]``) and version-1 springs as Box2D v3 joint records.

Body order. Stelkropp measures a joint's angle, translation and speeds as body ``a``'s relative
to body ``b`` (``b`` = None: the world). Box2D v3 measures body B's relative to body A, so for
revolute, prismatic, weld, distance and motor joints Stelkropp's ``a`` is Box2D's B and ``b``
(or a static ground body at the origin) is Box2D's A: angles, limits, motor speeds and
reference angles then carry over with their signs. The wheel joint is declared
``("wheel", chassis, wheel, ...)``: chassis = Box2D A (its frame holds the axis), wheel = B, so
its translation, limits and motor speed are the wheel's relative to the chassis (Box2D's
convention; ``WHEEL_A_IS_CHASSIS``).

Frames. Anchors and axes are world values at creation. Frame A sits at the anchor with its x
axis along the joint axis (prismatic, wheel; angle 0 otherwise); frame B is frame A turned by
minus the reference angle, so that Box2D's joint angle is theta_B - theta_A - reference (the
reference defaults to the bodies' relative angle at creation, so a new joint reads 0).

Box2D v3 has no mouse joint and its motor joint drives velocities and springs, not offsets:
``mouse`` is a motor joint from the ground whose frame A is the target, with only its linear
spring on (``hertz``, ``damping_ratio``, ``max_force``); ``motor`` is a motor joint whose frame
A is (linear_offset, angular_offset) in b's frame, driven by linear and angular springs of
``box2d.hertz`` (default 60 Hz, critically damped) capped at max_force / max_torque.
Springs (version 1) become soft distance joints with the spring's natural frequency for the
mass of a (or the pair's reduced mass), as bench/engines/pybox2d_sim.py does for pybox2d.
"""
from __future__ import annotations

import math

from .lib import OP_JOINT

KINDS = {"revolute": 0, "prismatic": 1, "weld": 2, "distance": 3, "wheel": 4, "motor": 5, "mouse": 5, "filter": 6}
WHEEL_A_IS_CHASSIS = True
MOTOR_HERTZ = 60.0
BIG = 3.4e38  # FLT_MAX: "no limit" for Box2D's float parameters


def _world_to_local(pose, p):
    (x, y), th = pose
    c, s = math.cos(th), math.sin(th)
    dx, dy = p[0] - x, p[1] - y
    return (c * dx + s * dy, -s * dx + c * dy)


def _local_to_world(pose, p):
    (x, y), th = pose
    c, s = math.cos(th), math.sin(th)
    return (x + c * p[0] - s * p[1], y + s * p[0] + c * p[1])


def _num(j, key, default, path, lo=None):
    v = j.get(key, default)
    if v is None:
        return None
    try:
        v = float(v)
    except (TypeError, ValueError):
        raise ValueError(f"{path}.{key}: must be a number; got {v!r}") from None
    if not math.isfinite(v) or (lo is not None and v < lo):
        raise ValueError(f"{path}.{key}: must be a finite number >= {lo}; got {v}" if lo is not None
                         else f"{path}.{key}: must be finite; got {v}")
    return v


def _pair(j, key, path):
    v = j.get(key)
    if v is None:
        return None
    if not (isinstance(v, (list, tuple)) and len(v) == 2):
        raise ValueError(f"{path}.{key}: expected [x, y]")
    return (float(v[0]), float(v[1]))


def _frames(j, kind, pa, pb, path):
    """(frameA, frameB) for Box2D bodies A (pose pa) and B (pose pb)."""
    axis = _pair(j, "axis", path) or ((0.0, 1.0) if kind == "wheel" else (1.0, 0.0))
    phi = math.atan2(axis[1], axis[0]) if kind in ("prismatic", "wheel") else 0.0
    local_a, local_b = _pair(j, "local_anchor_a", path), _pair(j, "local_anchor_b", path)
    swap = not (kind == "wheel" and WHEEL_A_IS_CHASSIS)
    if local_a is not None and local_b is not None:
        fa_p, fb_p = (local_b, local_a) if swap else (local_a, local_b)
    else:
        anchor = _pair(j, "anchor", path)
        if anchor is None:
            raise ValueError(f"{path}.anchor: required (a world point), or local_anchor_a and local_anchor_b")
        fa_p, fb_p = _world_to_local(pa, anchor), _world_to_local(pb, anchor)
    ref = _num(j, "reference_angle", None, path)
    if ref is None:
        ref = pb[1] - pa[1]
    beta_a = phi - pa[1]
    return (fa_p[0], fa_p[1], beta_a), (fb_p[0], fb_p[1], beta_a - ref)


def _limit(lo, hi):
    on = lo is not None or hi is not None
    return [1.0 if on else 0.0, -BIG if lo is None else lo, BIG if hi is None else hi]


def _spring(j, path, default_hertz=0.0, default_damping=0.0):
    hz = _num(j, "spring_hertz", default_hertz, path, 0.0)
    zeta = _num(j, "spring_damping_ratio", default_damping, path, 0.0)
    return [1.0 if hz > 0 else 0.0, hz, zeta]


def _motor(j, key_max, path):
    mx = _num(j, key_max, 0.0, path, 0.0)
    return [1.0 if mx > 0 else 0.0, mx, _num(j, "motor_speed", 0.0, path)]


def _params(j, kind, pa, pb, fa, fb, path):
    if kind == "revolute":
        return [*_spring(j, path), 0.0, *_limit(_num(j, "lower_angle", None, path), _num(j, "upper_angle", None, path)),
                *_motor(j, "max_motor_torque", path)]
    if kind == "prismatic":
        return [*_spring(j, path), 0.0, *_limit(_num(j, "lower", None, path), _num(j, "upper", None, path)),
                *_motor(j, "max_motor_force", path)]
    if kind == "weld":
        zeta = _num(j, "damping_ratio", 0.0, path, 0.0)
        return [_num(j, "linear_hertz", 0.0, path, 0.0), _num(j, "angular_hertz", 0.0, path, 0.0), zeta, zeta]
    if kind == "wheel":
        return [*_spring(j, path, 4.0, 0.7), *_limit(_num(j, "lower", None, path), _num(j, "upper", None, path)),
                *_motor(j, "max_motor_torque", path)]
    if kind == "distance":
        wa, wb = _local_to_world(pa, fa[:2]), _local_to_world(pb, fb[:2])
        length = _num(j, "length", None, path, 0.0)
        length = math.dist(wa, wb) if length is None else length
        lo, hi = _num(j, "min_length", None, path, 0.0), _num(j, "max_length", None, path, 0.0)
        hz, zeta = _num(j, "spring_hertz", 0.0, path, 0.0), _num(j, "spring_damping_ratio", 0.0, path, 0.0)
        # Box2D: a distance joint without its spring is rigid and ignores the limits; a rope
        # (limits only) is a spring of zero stiffness inside the limits.
        spring = hz > 0 or lo is not None or hi is not None
        return [length, 1.0 if spring else 0.0, hz, zeta, -BIG, BIG, *_limit(lo, hi), 0.0, 0.0, 0.0]
    if kind == "mouse":
        return [0.0, 0.0, 0.0, 0.0, 0.0, _num(j, "hertz", 5.0, path, 0.0), _num(j, "damping_ratio", 0.7, path, 0.0),
                _num(j, "max_force", 1000.0, path, 0.0), 0.0, 0.0, 0.0]
    if kind == "motor":
        hz = float(j.get("box2d", {}).get("hertz", MOTOR_HERTZ))
        return [0.0, 0.0, 0.0, 0.0, 0.0, hz, 1.0, _num(j, "max_force", 100.0, path, 0.0), hz, 1.0,
                _num(j, "max_torque", 100.0, path, 0.0)]
    return []


GROUND = (-1, ((0.0, 0.0), 0.0))


def joint_record(j, bodies, path):
    """(record, kind) for joint spec ``j``; ``bodies`` maps names to (slot, (position, angle))."""
    kind = j.get("kind")
    if kind not in KINDS:
        raise ValueError(f"{path}.kind: unknown joint kind {kind!r}; one of {', '.join(KINDS)}")

    def body(key):
        name = j.get(key)
        if name is None:
            return GROUND
        if name not in bodies:
            raise ValueError(f"{path}.{key}: no body named {name!r}")
        return bodies[name]
    ja, jb = body("a"), body("b")
    if ja is GROUND:
        raise ValueError(f"{path}.a: a joint needs a body a")
    if ja[0] == jb[0]:
        raise ValueError(f"{path}: a joint joins two different bodies")
    if kind == "mouse":
        (sa, pa), (sb, pb) = GROUND, ja
        target = _pair(j, "target", path)
        if target is None:
            raise ValueError(f"{path}.target: required for a mouse joint")
        fa, fb = (target[0], target[1], 0.0), (*_world_to_local(pb, target), 0.0)
    else:
        (sa, pa), (sb, pb) = (ja, jb) if (kind == "wheel" and WHEEL_A_IS_CHASSIS) else (jb, ja)
        if kind == "distance":
            aa, ab = _pair(j, "anchor_a", path), _pair(j, "anchor_b", path)
            la, lb = _pair(j, "local_anchor_a", path), _pair(j, "local_anchor_b", path)
            fb_p = la if la is not None else _world_to_local(pb, aa or pb[0])
            fa_p = lb if lb is not None else _world_to_local(pa, ab or pa[0])
            fa, fb = (*fa_p, 0.0), (*fb_p, 0.0)
        elif kind == "motor":
            off = _pair(j, "linear_offset", path) or (0.0, 0.0)
            fa, fb = (off[0], off[1], _num(j, "angular_offset", 0.0, path)), (0.0, 0.0, 0.0)
        else:
            fa, fb = _frames(j, kind, pa, pb, path)
    ext = j.get("box2d", {})
    params = _params(j, kind, pa, pb, fa, fb, path)
    rec = [OP_JOINT, KINDS[kind], sa, sb, *fa, *fb, 1.0 if j.get("collide_connected", False) else 0.0,
           float(ext.get("constraint_hertz", -1.0)), float(ext.get("constraint_damping_ratio", -1.0)),
           len(params), *params]
    return rec, kind


def spring_record(s, bodies, masses, path):
    """A version-1 spring as a soft Box2D distance joint (natural frequency for the spring's mass)."""
    ja = bodies.get(s.get("a"))
    if ja is None:
        raise ValueError(f"{path}.a: no body named {s.get('a')!r}")
    jb = GROUND if s.get("b") is None else bodies.get(s["b"])
    if jb is None:
        raise ValueError(f"{path}.b: no body named {s.get('b')!r}")
    la = tuple(map(float, s.get("anchor_a", (0, 0))))
    lb = tuple(map(float, s.get("anchor_b", (0, 0))))
    k, c = float(s.get("stiffness", 100.0)), float(s.get("damping", 0.0))
    ma = masses[ja[0]]
    m = ma if jb is GROUND or masses[jb[0]] == 0 else 1.0 / (1.0 / ma + 1.0 / masses[jb[0]])
    omega = math.sqrt(k / m) if m > 0 else 0.0
    zeta = c / (2.0 * math.sqrt(k * m)) if k > 0 and m > 0 else 0.0
    wa, wb = _local_to_world(ja[1], la), _local_to_world(jb[1], lb)
    rest = s.get("rest_length")
    length = math.dist(wa, wb) if rest is None else float(rest)
    params = [length, 1.0, omega / (2 * math.pi), zeta, -BIG, BIG, 0.0, 0.0, BIG, 0.0, 0.0, 0.0]
    return [OP_JOINT, KINDS["distance"], jb[0], ja[0], *lb, 0.0, *la, 0.0, 0.0, -1.0, -1.0, len(params), *params]
