"""pymunk (Chipmunk2D) behind the ``Sim`` interface.

Material mixing differs from Stelkropp's and is compensated per shape:

* friction -- Stelkropp combines by the geometric mean sqrt(mu_a mu_b); Chipmunk multiplies,
  so each pymunk shape gets sqrt(mu) and the product is again sqrt(mu_a mu_b).  pymunk has
  one Coulomb coefficient: the dynamic one is used.
* restitution -- Stelkropp takes the maximum; Chipmunk multiplies.  Static shapes with e = 0
  get e = 1 so that a dynamic body's own e is what a bounce off the ground uses (exact for
  body-vs-static contacts; between two dynamic bodies with e > 0 pymunk uses the product).

Solver settings: ``space.iterations = 10`` (its default), other Chipmunk parameters at their
defaults (``collision_slop`` 0.1 m, ``collision_bias`` (1-0.1)^60).
"""
from __future__ import annotations

import math

import numpy as np

from ..desc import spring_ends
from .base import Sim
from .pymunk_joints import add_joints
from .pymunk_shapes import add_parts

PYMUNK_ITERATIONS = 10


class PymunkSim(Sim):
    """pymunk running a description: ``iterations`` solver iterations (default 10, pymunk's own),
    other Chipmunk parameters at their defaults, sleeping off (on only where the description
    creates bodies asleep)."""

    engine = "pymunk"
    settings_label = f"iterations {PYMUNK_ITERATIONS}"

    def __init__(self, desc, iterations=PYMUNK_ITERATIONS):
        import pymunk
        super().__init__(desc)
        w = desc.get("world", {})
        sp = pymunk.Space()
        sp.gravity = tuple(w.get("gravity", (0.0, -9.81)))
        sp.iterations = int(iterations)
        sp.sleep_time_threshold = float("inf")
        self.space = sp
        self.bodies = []
        any_e = any(r["restitution"] > 0 for r in self.recs)
        for r in self.recs:
            kind = {"dynamic": pymunk.Body.DYNAMIC, "static": pymunk.Body.STATIC,
                    "kinematic": pymunk.Body.KINEMATIC}[r["kind"]]
            body = pymunk.Body(body_type=kind)
            body.position = r["position"]
            body.angle = r["angle"]
            shp = r["shape"]
            if r["parts"]:  # several fixtures or a version-2 shape (bench/engines/pymunk_shapes.py)
                sp.add(body)
                add_parts(pymunk, sp, body, r, any_e)
            elif hasattr(shp, "vertices"):
                s = pymunk.Poly(body, [tuple(map(float, v)) for v in shp.vertices], radius=0.0)
            else:
                s = pymunk.Circle(body, float(shp.radius), tuple(map(float, shp.offset)))
            if not r["parts"]:
                if kind == pymunk.Body.DYNAMIC:
                    s.density = r["density"]
                s.friction = math.sqrt(r["mu_d"])
                e = r["restitution"]
                s.elasticity = 1.0 if (r["kind"] != "dynamic" and e == 0.0 and any_e) else e
                sp.add(body, s)
            if kind != pymunk.Body.STATIC:
                body.velocity = r["velocity"]
                body.angular_velocity = r["angular_velocity"]
            self.bodies.append(body)
        for a, b, la, lb, k, c, rest in spring_ends(desc):
            ba = self.bodies[a]
            if b is None:
                bb, lbb = sp.static_body, lb
            else:
                bb, lbb = self.bodies[b], lb
            if rest is None:
                pa = ba.local_to_world(la)
                pb = bb.local_to_world(lbb)
                rest = (pa - pb).length
            sp.add(pymunk.DampedSpring(ba, bb, la, lbb, float(rest), k, c))
        add_joints(pymunk, sp, self.bodies, desc)  # the joint scenes' (bench/engines/pymunk_joints.py)
        self._create_asleep(sp, desc)

    def _create_asleep(self, sp, desc):
        """Bodies the description creates asleep (``awake: false``; smash's wall) go to sleep each
        alone (Chipmunk's ``cpBodySleep``), with sleeping on at the 0.5 s both other engines use:
        pymunk then wakes them on contact as they do."""
        asleep = [b for b, d in zip(self.bodies, desc["bodies"]) if d.get("kind", "dynamic") == "dynamic"
                  and not d.get("box2d", {}).get("awake", d.get("awake", True))]
        if asleep:
            sp.sleep_time_threshold = 0.5
            for b in asleep:
                b.sleep()

    def step(self):
        """One ``space.step(dt)``."""
        self.space.step(self.dt)

    def state(self):
        """(com, angle, v, w) read body by body."""
        bs = self.bodies
        n = len(bs)
        com = np.empty((n, 2))
        v = np.empty((n, 2))
        ang = np.empty(n)
        w = np.empty(n)
        for i, b in enumerate(bs):
            c = b.local_to_world(b.center_of_gravity)
            com[i] = (c.x, c.y)
            vv = b.velocity
            v[i] = (vv.x, vv.y)
            ang[i] = b.angle
            w[i] = b.angular_velocity
        return com, ang, v, w
