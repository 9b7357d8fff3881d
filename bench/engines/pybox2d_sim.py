"""pybox2d (Box2D 2.3) behind the ``Sim`` interface.

Box2D 2.3 combines friction by the geometric mean and restitution by the maximum, as
Stelkropp does; it has one Coulomb coefficient (the dynamic one is used).  Solver settings:
``Step(dt, 8, 3)``.  Box2D 2.3 has no plain spring: a soft distance joint of the same natural
frequency and damping ratio stands in for one.
"""
from __future__ import annotations

import math

import numpy as np

from ..desc import spring_ends
from .base import Sim

BOX2D_VELOCITY_ITERATIONS = 8
BOX2D_POSITION_ITERATIONS = 3


class Box2DSim(Sim):
    """pybox2d (Box2D 2.3) running a description: ``Step(dt, velocity_iterations,
    position_iterations)``, default 8 and 3; sleeping off."""

    engine = "pybox2d"
    settings_label = f"Step(dt, {BOX2D_VELOCITY_ITERATIONS}, {BOX2D_POSITION_ITERATIONS})"

    def __init__(self, desc, velocity_iterations=BOX2D_VELOCITY_ITERATIONS,
                 position_iterations=BOX2D_POSITION_ITERATIONS):
        import Box2D as b2
        super().__init__(desc)
        w = desc.get("world", {})
        world = b2.b2World(gravity=tuple(w.get("gravity", (0.0, -9.81))), doSleep=False)
        self.world = world
        self.vi, self.pi = int(velocity_iterations), int(position_iterations)
        self.bodies = []
        for r in self.recs:
            kw = dict(position=r["position"], angle=r["angle"], allowSleep=False)
            if r["kind"] == "static":
                body = world.CreateStaticBody(**kw)
            elif r["kind"] == "kinematic":
                body = world.CreateKinematicBody(**kw)
            else:
                body = world.CreateDynamicBody(**kw)
            shp = r["shape"]
            fk = dict(density=r["density"], friction=r["mu_d"], restitution=r["restitution"])
            if hasattr(shp, "vertices"):
                verts = [tuple(map(float, v)) for v in shp.vertices]
                if len(verts) > b2.b2_maxPolygonVertices:
                    raise ValueError("polygon has more vertices than Box2D 2.3 supports")
                body.CreatePolygonFixture(vertices=verts, **fk)
            else:
                body.CreateCircleFixture(radius=float(shp.radius), pos=tuple(map(float, shp.offset)), **fk)
            if r["kind"] != "static":
                body.linearVelocity = r["velocity"]
                body.angularVelocity = r["angular_velocity"]
            self.bodies.append(body)
        self._ground = None
        for a, b, la, lb, k, c, rest in spring_ends(desc):
            # Box2D 2.3 has no plain spring: a soft distance joint with the same natural frequency
            # (for the mass of body a) and damping ratio stands in for it.
            ba = self.bodies[a]
            if b is None:
                if self._ground is None:
                    self._ground = world.CreateStaticBody(position=(0, 0))
                bb, pb = self._ground, lb
            else:
                bb = self.bodies[b]
                pb = bb.GetWorldPoint(lb)
            m = ba.mass if b is None else 1.0 / (1.0 / ba.mass + 1.0 / bb.mass)
            omega = math.sqrt(k / m)
            zeta = c / (2.0 * math.sqrt(k * m)) if k > 0 else 0.0
            j = world.CreateDistanceJoint(bodyA=ba, bodyB=bb, anchorA=ba.GetWorldPoint(la), anchorB=pb,
                                          frequencyHz=omega / (2 * math.pi), dampingRatio=zeta)
            if rest is not None:
                j.length = float(rest)

    def step(self):
        """One ``world.Step``."""
        self.world.Step(self.dt, self.vi, self.pi)

    def state(self):
        """(com, angle, v, w) read body by body."""
        bs = self.bodies
        n = len(bs)
        com = np.empty((n, 2))
        v = np.empty((n, 2))
        ang = np.empty(n)
        w = np.empty(n)
        for i, b in enumerate(bs):
            c = b.worldCenter
            com[i] = (c[0], c[1])
            vv = b.linearVelocity
            v[i] = (vv[0], vv[1])
            ang[i] = b.angle
            w[i] = b.angularVelocity
        return com, ang, v, w
