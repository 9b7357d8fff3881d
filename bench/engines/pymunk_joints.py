"""A scene description's joints as pymunk (Chipmunk2D) constraints, for the joint benchmark scenes.

Anchors in a saved scene file are body coordinates of each body's origin (``local_anchor_a`` /
``local_anchor_b``; for the world, ``local_anchor_b`` is a world point), the frame pymunk's
bodies use too; a hand-written entry's world ``anchor`` / ``anchor_a`` / ``anchor_b`` / ``axis``
are turned into those at the bodies' starting poses (``_local_geometry``).  Kind by kind (Chipmunk's joint set, docs: pymunk.readthedocs.io, constraints):

* revolute -- PivotJoint; limits: RotaryLimitJoint(b, a), which bounds angle_a - angle_b
  (Chipmunk's cpRotaryLimitJoint bounds b->a - a->a), i.e. reference_angle + our angle; motor: SimpleMotor(a, b, rate), which holds w_a - w_b = rate (Chipmunk's cpSimpleMotor solves
  w_b - w_a + rate = 0), our motor_speed's sign; max_motor_torque is its max_force.
* distance -- rigid: PinJoint at the rest length; a rope or min/max: SlideJoint; a spring:
  DampedSpring with stiffness m_eff (2 pi f)^2 and damping 2 zeta m_eff (2 pi f), m_eff the two
  bodies' reduced mass (the same soft-constraint mapping as Box2D's, Catto GDC 2011).
* prismatic / wheel -- GrooveJoint: b's anchor slides in a groove on a along the axis, its ends
  at the limits (unlimited: +-100 m); a prismatic adds a GearJoint (ratio 1) against rotation;
  a wheel adds a DampedSpring along the axis and a SimpleMotor.
* weld -- PivotJoint plus GearJoint.  motor -- SimpleMotor with max_force = max_torque (a
  force-free one only switches the pair's collisions off, as ours does).
Every constraint gets ``collide_bodies = collide_connected``, as joined bodies do not collide here.
"""
from __future__ import annotations

import math

FREE = 100.0  # groove half-length (m) for an axis without limits


def _reduced_mass(a, b):
    inv = sum(1.0 / x.mass for x in (a, b) if x.body_type == x.DYNAMIC and x.mass > 0)
    return 1.0 / inv if inv > 0 else 0.0


def _spring(pymunk, a, b, la, lb, rest, hertz, zeta):
    m = _reduced_mass(a, b)
    om = 2.0 * math.pi * hertz
    return pymunk.DampedSpring(a, b, la, lb, rest, m * om * om, 2.0 * zeta * m * om)


def _groove(pymunk, a, b, la, lb, axis, lower, upper):
    """b's anchor on a groove through a's anchor: translation t of a relative to b puts b's
    anchor at la - t axis in a's frame, so the groove runs from la - upper axis to la - lower axis."""
    lo = -FREE if lower is None else lower
    hi = FREE if upper is None else upper
    g1 = (la[0] - hi * axis[0], la[1] - hi * axis[1])
    g2 = (la[0] - lo * axis[0], la[1] - lo * axis[1])
    return pymunk.GrooveJoint(a, b, g1, g2, lb)


def _local_geometry(jd, a, b) -> dict:
    """``jd`` with its world-coordinate geometry given in body coordinates, as a saved file has it."""
    out = dict(jd)
    pa = jd.get("anchor_a", jd.get("anchor", tuple(a.position)))
    pb = jd.get("anchor_b", jd.get("anchor", tuple(b.position)))
    if "local_anchor_a" not in jd:
        out["local_anchor_a"] = tuple(a.world_to_local(tuple(pa)))
    if "local_anchor_b" not in jd:
        out["local_anchor_b"] = tuple(b.world_to_local(tuple(pb)))
    out.setdefault("reference_angle", a.angle - b.angle)
    if "local_axis" not in jd and "axis" in jd:
        c, s = math.cos(a.angle), math.sin(a.angle)
        ux, uy = jd["axis"]
        n = math.hypot(ux, uy)
        out["local_axis"] = ((c * ux + s * uy) / n, (-s * ux + c * uy) / n)
    if jd["kind"] == "distance" and jd.get("length") is None:
        wa, wb = a.local_to_world(out["local_anchor_a"]), b.local_to_world(out["local_anchor_b"])
        out["length"] = (wa - wb).length
    return out


def constraints_for(pymunk, jd, a, b):
    """The pymunk constraints of one joint entry ``jd`` between bodies ``a`` and ``b`` (b: the
    space's static body for the world).  NotImplementedError for what no scene here uses."""
    jd = _local_geometry(jd, a, b)
    kind = jd["kind"]
    la = tuple(jd.get("local_anchor_a", (0.0, 0.0)))
    lb = tuple(jd.get("local_anchor_b", (0.0, 0.0)))
    out = []
    if kind in ("revolute", "weld"):
        out.append(pymunk.PivotJoint(a, b, la, lb))
        ref = jd.get("reference_angle", 0.0)
        if kind == "weld":
            out.append(pymunk.GearJoint(b, a, ref, 1.0))
        elif jd.get("lower_angle") is not None or jd.get("upper_angle") is not None:
            # RotaryLimitJoint(b, a) bounds a.angle - b.angle, which is ref + our angle
            lo = -math.inf if jd.get("lower_angle") is None else jd["lower_angle"]
            hi = math.inf if jd.get("upper_angle") is None else jd["upper_angle"]
            out.append(pymunk.RotaryLimitJoint(b, a, ref + max(lo, -1e6), ref + min(hi, 1e6)))
        if jd.get("spring_hertz", 0.0) > 0:
            raise NotImplementedError("revolute spring")
        if kind == "revolute" and jd.get("max_motor_torque", 0.0) > 0:
            m = pymunk.SimpleMotor(a, b, jd.get("motor_speed", 0.0))
            m.max_force = jd["max_motor_torque"]
            out.append(m)
    elif kind == "distance":
        length = jd["length"]
        lo, hi = jd.get("min_length"), jd.get("max_length")
        if jd.get("spring_hertz", 0.0) > 0:
            out.append(_spring(pymunk, a, b, la, lb, length, jd["spring_hertz"], jd.get("spring_damping_ratio", 0.0)))
            if lo is not None or hi is not None:
                out.append(pymunk.SlideJoint(a, b, la, lb, lo or 0.0, FREE if hi is None else hi))
        elif lo is not None or hi is not None:
            out.append(pymunk.SlideJoint(a, b, la, lb, lo or 0.0, FREE if hi is None else hi))
        else:
            pin = pymunk.PinJoint(a, b, la, lb)
            pin.distance = length
            out.append(pin)
    elif kind in ("prismatic", "wheel"):
        axis = tuple(jd.get("local_axis", (1.0, 0.0) if kind == "prismatic" else (0.0, 1.0)))
        out.append(_groove(pymunk, a, b, la, lb, axis, jd.get("lower"), jd.get("upper")))
        if kind == "prismatic":
            out.append(pymunk.GearJoint(b, a, jd.get("reference_angle", 0.0), 1.0))
            if jd.get("max_motor_force", 0.0) > 0 or jd.get("spring_hertz", 0.0) > 0:
                raise NotImplementedError("prismatic motor or spring")
        else:
            hz = jd.get("spring_hertz", 4.0)
            if hz > 0:  # a spring of rest length 1 m along the axis (its direction stays the axis's)
                top = (la[0] + axis[0], la[1] + axis[1])
                out.append(_spring(pymunk, a, b, top, lb, 1.0, hz, jd.get("spring_damping_ratio", 0.7)))
            if jd.get("max_motor_torque", 0.0) > 0:
                m = pymunk.SimpleMotor(a, b, jd.get("motor_speed", 0.0))
                m.max_force = jd["max_motor_torque"]
                out.append(m)
    elif kind == "motor":
        if jd.get("max_force", 100.0) > 0 or jd.get("max_torque", 100.0) > 0:
            raise NotImplementedError("motor joint with force")
        m = pymunk.SimpleMotor(a, b, 0.0)
        m.max_force = 0.0
        out.append(m)
    else:
        raise NotImplementedError(f"{kind} joint")
    for c in out:
        c.collide_bodies = bool(jd.get("collide_connected", False))
    return out


def add_joints(pymunk, space, bodies, desc):
    """Add the constraints of every joint of ``desc`` (``bodies``: pymunk bodies in description order)."""
    names = {b.get("name", i): i for i, b in enumerate(desc["bodies"])}
    for jd in desc.get("joints", []):
        a = bodies[names[jd["a"]]]
        b = space.static_body if jd.get("b") is None else bodies[names[jd["b"]]]
        if a.body_type != a.DYNAMIC and b.body_type != b.DYNAMIC:
            continue  # between two bodies that never move it does nothing (pymunk refuses it)
        space.add(*constraints_for(pymunk, jd, a, b))
