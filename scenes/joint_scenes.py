"""The shipped scenes built from joints (issue 14): pendulums, Newton's cradle, a hinged bridge,
a wrecking ball, a crank-driven piston and Box2D v3's joint_grid benchmark.  The machines (car,
ragdoll, Theo Jansen walker) are in scenes/joint_machines.py.

Each function returns plain scene data (scenes/scene_kit.py); scenes/make_scenes.py turns it into
the canonical file.  Numbers are in SI units (m, kg, s, rad); g = 10 m/s^2.
"""
from __future__ import annotations

import math

from joint_machines import car, ragdoll, walker
from scene_kit import body, box, circle, ground, hinge, joint, r, scene, static


def pendulum():
    """Three rods on world hinges (1, 2 and 3 m: periods 2 pi sqrt(2 L / 3 g) = 1.62, 2.29,
    2.81 s at small amplitude) and a disc on a rigid distance joint, all released at 30 degrees."""
    bodies, joints = [], []
    th = math.radians(30.0)
    for k, length in enumerate((1.0, 2.0, 3.0)):
        px, py = -6.0 + 3.0 * k, 8.0
        c = (px + 0.5 * length * math.sin(th), py - 0.5 * length * math.cos(th))
        bodies.append(body(box(0.1, length), c[0], c[1], f"rod{k}", angle=r(th)))
        joints.append(hinge(f"rod{k}", None, (px, py), f"pivot{k}"))
    px, py, length = 4.0, 8.0, 2.0
    p = (px + length * math.sin(th), py - length * math.cos(th))
    bodies.append(body(circle(0.25), p[0], p[1], "bob"))
    joints.append(joint("distance", "bob", None, "string", anchor_a=p, anchor_b=(px, py)))
    return scene("Pendulum", "Three rods of 1, 2 and 3 m on world hinges and a disc on a rigid 2 m distance "
                             "joint, released at 30 degrees.  A rod of length L swings with period "
                             "2 pi sqrt(2L / 3g) (1.62, 2.29, 2.81 s here, a few percent more at this "
                             "amplitude); the disc like a point pendulum, 2 pi sqrt(L / g) = 2.81 s.",
                 bodies, joints=joints, camera={"center": [-0.5, 5.5], "zoom": 45.0})


def double_pendulum():
    """Two double pendulums of 1 m rods released horizontal, the second 0.001 rad lower: their
    motions part after a few seconds (chaos), though each conserves its energy."""
    bodies, joints = [], []
    for k, (px, tilt) in enumerate(((-3.0, 0.0), (3.0, 0.001))):
        py = 7.0
        names = (f"upper{k}", f"lower{k}")
        for i, nm in enumerate(names):
            c = (px + (i + 0.5) * math.cos(tilt), py - (i + 0.5) * math.sin(tilt))
            bodies.append(body(box(1.0, 0.1), c[0], c[1], nm, angle=r(-tilt)))
        joints.append(hinge(names[0], None, (px, py), f"shoulder{k}"))
        joints.append(hinge(names[1], names[0], (px + math.cos(tilt), py - math.sin(tilt)), f"elbow{k}"))
    return scene("Double pendulum", "Two frictionless double pendulums (two 1 m rods on hinges each) released "
                                    "horizontal, the right one 0.001 rad lower.  They follow each other for a "
                                    "few seconds and then part: the double pendulum is chaotic.",
                 bodies, joints=joints, camera={"center": [0.0, 6.8], "zoom": 75.0})


def newtons_cradle():
    """Five balls of radius 0.5 m on rigid 4 m distance joints, touching; restitution 1, no
    friction.  The first is pulled out to 50 degrees."""
    bodies, joints = [], []
    n, rad, length, top = 5, 0.5, 4.0, 8.0
    th = math.radians(50.0)
    for k in range(n):
        ax = (k - 0.5 * (n - 1)) * 2.0 * rad * 1.0005  # 0.25 mm gaps: no contact at the start
        p = (ax - length * math.sin(th), top - length * math.cos(th)) if k == 0 else (ax, top - length)
        bodies.append(body(circle(rad), p[0], p[1], f"ball{k}", restitution=1.0, friction=0.0))
        joints.append(joint("distance", f"ball{k}", None, f"wire{k}", anchor_a=p, anchor_b=(ax, top)))
    bodies.append(static(box(6.0, 0.3), 0.0, top + 0.15, "frame"))
    return scene("Newton's cradle", "Five touching balls (restitution 1, no friction) on rigid 4 m distance "
                                    "joints; the first is released from 50 degrees.  Momentum and energy pass "
                                    "through the row: how cleanly depends on the solver mode.",
                 bodies, joints=joints, camera={"center": [0.0, 4.5], "zoom": 55.0})


def _arc_pins(links, pitch, chord):
    """Pins of a chain of ``links`` equal links of length ``pitch`` hung between two pins ``chord``
    apart at height 0: on a circular arc (the links are its chords).  With 2 R sin(phi / 2) = pitch
    and 2 R sin(links phi / 2) = chord, phi is found by bisection."""
    lo, hi = 1e-9, 2.0 * math.pi / links
    for _ in range(200):
        phi = 0.5 * (lo + hi)
        if math.sin(0.5 * links * phi) / math.sin(0.5 * phi) > chord / pitch:
            lo = phi
        else:
            hi = phi
    rad = 0.5 * pitch / math.sin(0.5 * phi)
    cy = rad * math.cos(0.5 * links * phi)
    return [(rad * math.sin((k - 0.5 * links) * phi), cy - rad * math.cos((k - 0.5 * links) * phi))
            for k in range(links + 1)]


def hinge_bridge():
    """scenes/chain_bridge.json's planks and crates on hinges: 16 planks of 0.9 m, hinged 1 m
    apart, hung with 1.5 % slack between two towers (a straight chain of rigid links cannot carry a
    load: the tension it needs grows without bound as the sag goes to 0)."""
    planks, w, h, y = 16, 0.9, 0.2, -0.1
    chord = planks * 1.0 * 0.985
    bodies = [ground(40.0, y=-3.0),
              static(box(1.0, 3.0), -0.5 * chord - 0.5, -1.5, "tower_left"),
              static(box(1.0, 3.0), 0.5 * chord + 0.5, -1.5, "tower_right")]
    pins = [(x, y + py) for x, py in _arc_pins(planks, 1.0, chord)]
    # hinge friction (a motor at speed 0, 0.5 N m): the swaying dies out and the bridge sleeps
    rub = dict(motor_speed=0.0, max_motor_torque=0.5)
    joints = []
    for i in range(planks):
        (x0, y0), (x1, y1) = pins[i], pins[i + 1]
        bodies.append(body(box(w, h), 0.5 * (x0 + x1), 0.5 * (y0 + y1), f"plank{i}", density=2.0,
                           angle=r(math.atan2(y1 - y0, x1 - x0))))
        b = "tower_left" if i == 0 else f"plank{i - 1}"
        joints.append(hinge(f"plank{i}", b, pins[i], "anchor_left" if i == 0 else f"link{i - 1}", **rub))
    joints.append(hinge(f"plank{planks - 1}", "tower_right", pins[-1], "anchor_right", **rub))
    for k, x in enumerate((-3.0, -0.5, 2.5)):
        bodies.append(body(box(0.8, 0.8), x, 2.0 + k, f"crate{k}", density=0.5))
    return scene("Hinge bridge", f"The chain bridge on hinges: {planks} planks on revolute joints 1 m apart, "
                                 "hung between two towers with 1.5 % slack (a straight chain of rigid links "
                                 "cannot carry a load), under the three crates of scenes/chain_bridge.json.  "
                                 "The hinges have a little friction (0.5 N m): the bridge comes to rest and "
                                 "sleeps.",
                 bodies, joints=joints, camera={"center": [0.0, -1.0], "zoom": 45.0})


def wrecking_ball():
    """A 0.75 m ball (density 1.5) on a chain of 14 hinged links, raised horizontal and let go into a
    wall of crates; a distance joint with max_length only (a rope) caps the chain's stretch, as
    Box2D's rope joint did."""
    top, links, lw = (0.0, 9.0), 14, 0.5
    bodies = [ground(40.0)]
    joints = []
    prev = None
    for i in range(links):
        nm = f"link{i}"
        bodies.append(body(box(lw, 0.125), top[0] - (i + 0.5) * lw, top[1], nm, density=4.0))
        joints.append(hinge(nm, prev, (top[0] - i * lw, top[1]), f"hinge{i}"))
        prev = nm
    rad = 0.75
    end = top[0] - links * lw
    # 2.65 kg on 0.25 kg links: a 1:10 mass ratio the iterative modes still hold together
    bodies.append(body(circle(rad), end - rad, top[1], "ball", density=1.5))
    joints.append(hinge("ball", prev, (end, top[1]), "hook"))
    reach = links * lw + rad
    joints.append(joint("distance", "ball", None, "rope", anchor_a=(end - rad, top[1]), anchor_b=top,
                        max_length=r(reach)))
    for col in range(3):
        for row in range(8):
            bodies.append(body(box(0.6, 0.6), 1.3 + 0.62 * col, 0.3 + 0.6 * row, f"crate{col}_{row}",
                               friction=0.6))
    return scene("Wrecking ball", "A heavy ball on a chain of 14 hinged links swings from horizontal into a wall of "
                                  "24 crates.  A rope (a distance joint with only max_length) from the pivot to "
                                  "the ball keeps the chain from stretching past its length.",
                 bodies, joints=joints, camera={"center": [-1.0, 1.5], "zoom": 38.0})


def piston():
    """A crank-slider: a motor turns a disc (1 rad/s), a 4 m rod on a pin 0.8 m off its centre
    drives a piston held on a vertical prismatic joint, with two crates riding on the piston."""
    cx, cy, pin, rod = 0.0, 2.0, 0.8, 4.0
    bodies = [ground(20.0),
              body(circle(1.0), cx, cy, "crank", density=2.0),
              body(box(0.3, rod), cx, cy + pin + 0.5 * rod, "rod"),
              body(box(1.6, 0.8), cx, cy + pin + rod + 0.4, "piston", density=2.0)]
    top = cy + pin + rod + 0.8
    bodies.append(body(box(0.8, 0.8), cx, top + 0.4, "crate0", friction=0.6))
    bodies.append(body(box(0.6, 0.6), cx + 0.1, top + 1.1, "crate1", friction=0.6))
    joints = [hinge("crank", None, (cx, cy), "crankshaft", motor_speed=1.0, max_motor_torque=2000.0),
              hinge("rod", "crank", (cx, cy + pin), "crank_pin"),
              hinge("piston", "rod", (cx, cy + pin + rod), "wrist_pin"),
              joint("prismatic", "piston", None, "cylinder", anchor=(cx, cy + pin + rod + 0.4), axis=(0.0, 1.0),
                    lower=r(-2.0 * pin - 0.05), upper=0.05)]
    return scene("Piston", "A crank-slider: a motor hinge turns a disc at 1 rad/s (up to 2000 N m), a 4 m "
                           "connecting rod on a pin 0.8 m off-centre drives a piston on a vertical prismatic "
                           "joint (1.6 m stroke, limits just outside it), and two crates ride on top.",
                 bodies, joints=joints, camera={"center": [0.0, 2.5], "zoom": 50.0})


def joint_grid(n=20):
    """Box2D v3's joint_grid benchmark (shared/benchmarks.c) at its debug size: an n x n grid of
    0.4 m discs 1 m apart, each hinged to its upper and left neighbour at the midpoint, the top
    row's middle seven static.  Box2D filters disc-disc contacts out; there is no filter here, so
    discs that are not neighbours collide when the net folds."""
    bodies, joints = [], []
    top = float(n)
    for k in range(n):
        for i in range(n):
            nm = f"d{k}_{i}"
            kind = "static" if (n // 2 - 3 <= k <= n // 2 + 3 and i == 0) else "dynamic"
            x, y = k - 0.5 * (n - 1), top - i
            bodies.append(body(circle(0.4), x, y, nm, **({"kind": "static"} if kind == "static" else {})))
            if i > 0:
                joints.append(hinge(nm, f"d{k}_{i - 1}", (x, y + 0.5)))
            if k > 0:
                joints.append(hinge(nm, f"d{k - 1}_{i}", (x - 0.5, y)))
    return scene(f"Joint grid {n}", f"Box2D v3's joint_grid benchmark at its debug size: {n} x {n} discs "
                                   f"(radius 0.4 m, 1 m apart) hinged to their neighbours, {len(joints)} "
                                   "revolute joints, hanging from seven static discs in the top row.  Sleeping "
                                   "is off, as in the benchmark.  Try dragging a disc of the bottom row and "
                                   "throwing the net.",
                 bodies, joints=joints, camera={"center": [0.0, 0.6 * n], "zoom": 600.0 / (n * 1.6)},
                 sleeping=False)


JOINT_SCENES = {
    "pendulum": pendulum, "double_pendulum": double_pendulum, "newtons_cradle": newtons_cradle,
    "hinge_bridge": hinge_bridge, "wrecking_ball": wrecking_ball, "piston": piston,
    "joint_grid": joint_grid, "ragdoll": ragdoll, "car": car, "walker": walker,
}
