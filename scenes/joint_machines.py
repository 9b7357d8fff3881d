"""The jointed machines among the shipped scenes (issue 14): the car on wheel joints, the ragdoll
and the Theo Jansen walker.  Plain scene data, as in scenes/joint_scenes.py.

Bodies here have no collision filter (Box2D gives a ragdoll's or a walker's parts one negative
group); where two parts that no joint holds must not touch, a motor joint with max_force = 0 and
max_torque = 0 joins them: it exerts nothing, and joined bodies do not collide (the role of
Box2D v3's filter joint, samples/sample_joints.cpp FilterJoint).
"""
from __future__ import annotations

import math

from scene_kit import body, box, circle, ground, hinge, joint, poly, pt, r, rotate, scene, static


def no_collide(a, b):
    """A force-free motor joint: its only effect is that ``a`` and ``b`` do not collide."""
    return joint("motor", a, b, f"nocollide_{a}_{b}", max_force=0.0, max_torque=0.0)


# -- the car -----------------------------------------------------------------------------------
def _terrain(x0=-22.0, x1=10.0, step=2.0):
    """Rolling hills as convex quads between the points of a height profile (flat where it
    starts), and a wall at the far end: a course short enough to stay in one view, so the car
    climbs the hills in sight and stops against the wall."""
    xs = [x0 + step * i for i in range(int((x1 - x0) / step) + 1)]

    def h(x):
        return 0.0 if x < -8.0 else 0.7 * math.sin(0.3 * (x + 8.0)) ** 2 + 0.25 * math.sin(1.1 * x)

    out = []
    for i in range(len(xs) - 1):
        a, b = xs[i], xs[i + 1]
        c = 0.5 * (a + b)
        out.append(static(poly([(a - c, -2.0), (b - c, -2.0), (b - c, h(b)), (a - c, h(a))]), c, 0.0,
                          f"ground{i}", friction=0.9))
    out.append(static(box(1.0, 6.0), x1 + 0.5, 1.0, "end_wall"))
    return out


def car():
    """A chassis on two disc wheels held by wheel joints (suspension 5 Hz / 4 Hz, damping ratio 0.7,
    travel limits), the rear one driven by a motor, on rolling terrain."""
    cx, cy = -16.0, 1.35
    hull = [(-1.5, -0.4), (1.5, -0.4), (1.5, 0.05), (0.1, 0.85), (-1.1, 0.85), (-1.5, 0.25)]
    bodies = _terrain()
    bodies.append(body(poly(hull), cx, cy, "chassis", density=1.0, friction=0.6))
    rad = 0.4
    joints = []
    for side, dx, hz in (("rear", -1.0, 4.0), ("front", 1.05, 5.0)):
        wx, wy = cx + dx, cy - 0.8
        bodies.append(body(circle(rad), wx, wy, f"wheel_{side}", friction=1.2))
        # body_a is the chassis: the axis lives in its frame; the motor's speed is the chassis's
        # relative to the wheel, so a positive speed turns the wheel clockwise (forwards, +x)
        drive = dict(motor_speed=12.0, max_motor_torque=25.0) if side == "rear" else {}
        joints.append(joint("wheel", "chassis", f"wheel_{side}", f"axle_{side}", anchor=(wx, wy), axis=(0.0, 1.0),
                            spring_hertz=hz, spring_damping_ratio=0.7, lower=-0.25, upper=0.25, **drive))
    return scene("Car", "A car on wheel joints: a chassis on two disc wheels with sprung suspension (4 Hz rear, "
                        "5 Hz front, damping ratio 0.7, 0.25 m travel each way), the rear wheel driven by a "
                        "motor (12 rad/s, up to 25 N m), over rolling hills of convex static quads to a wall.  "
                        "Try selecting the rear axle and setting a negative motor speed to drive back.",
                 bodies, joints=joints, camera={"center": [-5.5, 1.0], "zoom": 26.0})


# -- the ragdoll -------------------------------------------------------------------------------
# Box2D v3's human (shared/human.c) seen from the front: its heights and limit ranges at scale s,
# arms hanging beside the torso and the legs apart so no two parts overlap at the start.  Each
# part: (name, parent, box w x h or circle radius, centre, joint anchor, (lower, upper) limits,
# joint friction scale).  Limits of the left side mirror the right's (angles are the part's
# relative to its parent, counter-clockwise).
_PI = math.pi
_PARTS = (
    ("hip", None, (0.28, 0.2), (0.0, 0.95), None, None, 0.0),
    ("torso", "hip", (0.3, 0.42), (0.0, 1.2), (0.0, 1.0), (-0.15 * _PI, 0.15 * _PI), 0.5),
    ("head", "torso", 0.11, (0.0, 1.5), (0.0, 1.4), (-0.15 * _PI, 0.15 * _PI), 0.25),
    ("upper_arm_r", "torso", (0.08, 0.3), (0.2, 1.21), (0.2, 1.35), (-0.1 * _PI, 0.8 * _PI), 0.5),
    ("lower_arm_r", "upper_arm_r", (0.07, 0.28), (0.2, 0.94), (0.2, 1.07), (-0.2 * _PI, 0.3 * _PI), 0.1),
    ("upper_leg_r", "hip", (0.12, 0.34), (0.08, 0.78), (0.08, 0.92), (-0.05 * _PI, 0.3 * _PI), 1.0),
    ("lower_leg_r", "upper_leg_r", (0.1, 0.36), (0.08, 0.46), (0.08, 0.62), (-0.1 * _PI, 0.1 * _PI), 0.5),
)


def _mirror(part):
    name, parent, shape, c, anchor, lim, fs = part
    if not name.endswith("_r"):
        return None
    flip = (lambda n: n[:-2] + "_l" if n.endswith("_r") else n)
    return (flip(name), flip(parent), shape, (-c[0], c[1]), (-anchor[0], anchor[1]), (-lim[1], -lim[0]), fs)


def human(prefix, origin, s=2.0, tilt=0.0, friction_torque=0.25):
    """One ragdoll of scale ``s`` (Box2D's human is 1.6 m at s = 1) with its feet at ``origin``,
    turned by ``tilt`` rad; joint friction: a motor with speed 0 and max torque
    ``friction_torque`` N m times the part's friction scale (Box2D's frictionScale)."""
    parts = list(_PARTS) + [m for m in map(_mirror, _PARTS) if m]
    bodies, joints = [], []

    def place(p):
        q = rotate((s * p[0], s * (p[1] - 0.275)), tilt)  # Box2D's feet are 0.275 s above its origin
        return (origin[0] + q[0], origin[1] + q[1])

    for name, parent, shape, c, anchor, lim, fs in parts:
        spec = circle(s * shape) if isinstance(shape, float) else box(s * shape[0], s * shape[1])
        x, y = place(c)
        bodies.append(body(spec, x, y, prefix + name, angle=r(tilt), friction=0.6))
        if parent is None:
            continue
        joints.append(hinge(prefix + name, prefix + parent, place(anchor), prefix + name + "_joint",
                            lower_angle=r(lim[0]), upper_angle=r(lim[1]), motor_speed=0.0,
                            max_motor_torque=r(fs * friction_torque * s ** 3 / 8.0)))
    return bodies, joints


def ragdoll():
    """Three ragdolls like Box2D's human (limits, joint friction) tumbling down a flight of steps."""
    bodies = [ground(40.0, friction=0.7)]
    for k in range(6):
        w = 9.0 - 1.5 * k
        bodies.append(static(box(w, 0.6), -6.0 + 0.5 * (9.0 - w), 0.3 + 0.6 * k, f"step{k}", friction=0.7))
    joints = []
    for k, (x, y, tilt) in enumerate(((2.5, 5.0, 0.0), (0.0, 8.5, 0.6), (-2.5, 12.0, -1.2))):
        b, j = human(f"r{k}_", (x, y), tilt=tilt)
        bodies += b
        joints += j
    return scene("Ragdoll", "Three ragdolls after Box2D v3's human (shared/human.c, seen from the front, twice its "
                            "size): eleven boxes and a head on revolute joints with angle limits and joint "
                            "friction (a motor with speed 0 and a small max torque), dropped onto a flight of "
                            "steps.",
                 bodies, joints=joints, camera={"center": [-1.0, 1.0], "zoom": 40.0})


# -- the Theo Jansen walker ------------------------------------------------------------------------
# Box2D's "Theo Jansen" sample (the v2.4 testbed; not among this reference's v3 samples): the leg's
# six points relative to the crank's rest point, the crank (radius 0.8 m) and the motor.
_LEG = ((5.4, -6.1), (7.2, -1.2), (4.3, -1.9), (3.1, 0.8), (6.0, 1.5), (2.5, 3.7))
_CRANK = 0.8


def _circle_meet(c0, r0, c1, r1, sign):
    """The point at r0 from c0 and r1 from c1 on the side ``sign`` of the line c0 -> c1."""
    dx, dy = c1[0] - c0[0], c1[1] - c0[1]
    d = math.hypot(dx, dy)
    a = (r0 * r0 - r1 * r1 + d * d) / (2 * d)
    h = math.sqrt(max(r0 * r0 - a * a, 0.0))
    mx, my = c0[0] + a * dx / d, c0[1] + a * dy / d
    return (mx - sign * h * dy / d, my + sign * h * dx / d)


def _side(c0, c1, p):
    return 1.0 if (c1[0] - c0[0]) * (p[1] - c0[1]) - (c1[1] - c0[1]) * (p[0] - c0[0]) > 0 else -1.0


def _dist(p, q):
    return math.hypot(p[0] - q[0], p[1] - q[1])


def leg_pose(sx, phase):
    """The leg's joint points with the crank turned by ``phase``: the linkage closed by circle
    intersections (each point keeps the side it has at phase 0), so the legs start assembled."""
    p1, p2, p3, p4, p5, p6 = [(sx * x, y) for x, y in _LEG]
    c0 = (0.0, 0.0)
    c = rotate((0.0, -_CRANK), phase)
    c = (c[0], c[1] + _CRANK)
    n6 = _circle_meet(p4, _dist(p4, p6), c, _dist(c0, p6), _side(p4, c0, p6))
    beta = math.atan2(n6[1] - p4[1], n6[0] - p4[0]) - math.atan2(p6[1] - p4[1], p6[0] - p4[0])
    d5 = rotate((p5[0] - p4[0], p5[1] - p4[1]), beta)
    n5 = (p4[0] + d5[0], p4[1] + d5[1])
    n3 = _circle_meet(p4, _dist(p4, p3), c, _dist(c0, p3), _side(p4, c0, p3))
    n2 = _circle_meet(n3, _dist(p3, p2), n5, _dist(p5, p2), _side(p3, p5, p2))
    alpha = math.atan2(n2[1] - n3[1], n2[0] - n3[0]) - math.atan2(p2[1] - p3[1], p2[0] - p3[0])
    return dict(c=c, p2=n2, p3=n3, p4=p4, p5=n5, p6=n6, alpha=alpha, beta=beta)


def _leg(tag, sx, phase, off):
    """Two triangles and their joints; returns (bodies, joints, body names)."""
    p1, p2, p3, p4, p5, p6 = [(sx * x, y) for x, y in _LEG]
    k = leg_pose(sx, phase)
    w = (lambda p: (p[0] + off[0], p[1] + off[1]))
    # thigh: the triangle p1 p2 p3 in a frame whose origin is the crank's rest point
    o1 = rotate(p3, k["alpha"])
    o1 = (k["p3"][0] - o1[0], k["p3"][1] - o1[1])
    b1, b2 = f"leg{tag}_foot", f"leg{tag}_knee"
    bodies = [body(poly([p1, p2, p3]), *w(o1), b1, angle=r(k["alpha"]), friction=0.6),
              body(poly([(0, 0), (p5[0] - p4[0], p5[1] - p4[1]), (p6[0] - p4[0], p6[1] - p4[1])]), *w(p4), b2,
                   angle=r(k["beta"]), friction=0.6)]
    # soft distance joints (10 Hz, damping ratio 0.5) as in the sample: they take up the jitter
    soft = dict(spring_hertz=10.0, spring_damping_ratio=0.5)
    joints = [joint("distance", b1, b2, f"{b1}_p2p5", anchor_a=w(k["p2"]), anchor_b=w(k["p5"]), **soft),
              joint("distance", b1, b2, f"{b1}_p3p4", anchor_a=w(k["p3"]), anchor_b=w(k["p4"]), **soft),
              joint("distance", b1, "wheel", f"{b1}_crank", anchor_a=w(k["p3"]), anchor_b=w(k["c"]), **soft),
              joint("distance", b2, "wheel", f"{b2}_crank", anchor_a=w(k["p6"]), anchor_b=w(k["c"]), **soft),
              hinge(b2, "chassis", w(p4), f"{b2}_hip")]
    return bodies, joints, (b1, b2)


def walker():
    """Theo Jansen's linkage: a motor turns a crank wheel on a chassis; six legs (three crank phases
    120 degrees apart on each side) walk it over a floor towards a few balls."""
    off = (0.0, 8.0)
    bodies = [static(box(60.0, 1.0), 0.0, -0.5, "ground", friction=0.6),
              static(box(1.0, 10.0), -30.5, 5.0, "wall_left"), static(box(1.0, 10.0), 30.5, 5.0, "wall_right")]
    # a few balls just ahead of it (not strewn over the whole floor: framing them all made the
    # walker a few pixels tall)
    bodies += [body(circle(0.25), 14.0 + 1.5 * i, 0.25, f"ball{i}") for i in range(8)]
    pivot = (off[0], off[1] + _CRANK)
    bodies.append(body(box(5.0, 2.0), *pivot, "chassis"))
    bodies.append(body(circle(1.6), *pivot, "wheel"))
    joints = [hinge("wheel", "chassis", pivot, "motor", motor_speed=-2.0, max_motor_torque=400.0)]
    sides = {-1.0: [], 1.0: []}
    for sx in (-1.0, 1.0):
        for k, phase in enumerate((0.0, 2.0 * math.pi / 3.0, -2.0 * math.pi / 3.0)):
            b, j, names = _leg(f"{'lr'[sx > 0]}{k}", sx, phase, off)
            bodies += b
            joints += j
            sides[sx].append(names)
    # the three legs of a side share the plane in 2D: keep them from colliding with each other
    for legs in sides.values():
        for i in range(3):
            for k in range(i + 1, 3):
                joints += [no_collide(a, b) for a in legs[i] for b in legs[k]]
    return scene("Theo Jansen walker", "Theo Jansen's strandbeest linkage after Box2D's sample: a motor (2 rad/s, "
                                       "400 N m) turns the crank wheel, six legs of two triangles and four soft "
                                       "distance joints each (10 Hz) walk the chassis over a floor with a few "
                                       "balls.  Legs of one side would pass each other in depth: force-free motor "
                                       "joints stop them colliding.",
                 bodies, joints=joints, camera={"center": [12.5, 6.0], "zoom": 22.0}, sleeping=False)
