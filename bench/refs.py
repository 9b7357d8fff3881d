"""One scene description, three engines: Stelkropp, pymunk (Chipmunk2D) and pybox2d (Box2D 2.3).

A scene description is a dict in the scene-file format (``scenes/*.json``,
``"format": "stelkropp.scene"``).  ``load_desc`` reads a shipped scene file;
the generators below (``pyramid``, ``rain``, ``columns``) build the benchmark
scenes in code when no file ships them, in the same format.  From one
description ``build(engine, desc, ...)`` returns a ``Sim``: the same bodies,
vertices (taken from ``physics.Polygon``, so identical), masses (density x
area), friction, restitution, gravity, dt and springs in each engine, with
sleeping off.

Material mixing differs between engines and is compensated per shape:

* friction -- Stelkropp combines by the geometric mean sqrt(mu_a mu_b);
  Box2D 2.3 does the same (b2MixFriction); Chipmunk multiplies, so each
  pymunk shape gets sqrt(mu) and the product is again sqrt(mu_a mu_b).
  The references have one Coulomb coefficient: the dynamic one is used.
* restitution -- Stelkropp and Box2D take the maximum; Chipmunk multiplies.
  pymunk static shapes with e = 0 get e = 1 so that a dynamic body's own e
  is what a bounce off the ground uses (exact for body-vs-static contacts;
  between two dynamic bodies with e > 0 pymunk uses the product).

Reference solver settings: pymunk ``space.iterations = 10`` (its default),
other Chipmunk parameters at their defaults (``collision_slop`` 0.1 m,
``collision_bias`` (1-0.1)^60); pybox2d ``Step(dt, 8, 3)``.
"""
from __future__ import annotations

import copy
import json
import math
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
SCENES = ROOT / "scenes"

PYMUNK_ITERATIONS = 10
BOX2D_VELOCITY_ITERATIONS = 8
BOX2D_POSITION_ITERATIONS = 3

ENGINES = ("stelkropp", "pymunk", "pybox2d")


# -- descriptions ---------------------------------------------------------------
def _desc(name, description, bodies, springs=(), gravity=(0.0, -10.0), dt=1 / 60):
    return {"format": "stelkropp.scene", "version": 1, "name": name, "description": description,
            "world": {"gravity": list(gravity), "dt": dt, "sleeping": False},
            "bodies": list(bodies), "springs": list(springs)}


def box(w, h, x, y, kind="dynamic", angle=0.0, friction=0.6, restitution=0.0, density=1.0, name=None,
        velocity=(0.0, 0.0)):
    b = {"shape": {"box": [w, h]}, "position": [x, y], "friction": friction, "kind": kind,
         "restitution": restitution, "density": density}
    if angle:
        b["angle"] = angle
    if velocity != (0.0, 0.0):
        b["velocity"] = list(velocity)
    if name:
        b["name"] = name
    return b


def pyramid(base=20, friction=0.6):
    """Boxes 1x1 in a pyramid of ``base`` (base*(base+1)/2 boxes) on a static ground."""
    bodies = [box(max(40.0, 2.0 * base + 20), 1.0, 0.0, -0.5, kind="static", friction=friction, name="ground")]
    for row in range(base):
        for k in range(base - row):
            x = -0.5 * base + 0.5 + 0.5 * row + k
            bodies.append(box(1.0, 1.0, x, 0.5 + row, friction=friction))
    n = len(bodies) - 1
    return _desc(f"Pyramid {base}", f"{n} boxes (1x1) in a pyramid of base {base} on static ground", bodies)


def rain(n=1000, width=40.0, friction=0.6, seed=1):
    """``n`` 1x1 boxes dropped from a grid of columns into an open container ``width`` metres wide."""
    rng = np.random.default_rng(seed)
    wall_h = 4.0 + 1.25 * n / width
    bodies = [box(width + 2.0, 1.0, 0.0, -0.5, kind="static", friction=friction, name="floor"),
              box(1.0, wall_h, -0.5 * width - 0.5, 0.5 * wall_h, kind="static", friction=friction, name="left"),
              box(1.0, wall_h, 0.5 * width + 0.5, 0.5 * wall_h, kind="static", friction=friction, name="right")]
    cols = int((width - 2.0) // 1.5)
    for i in range(n):
        c, r = i % cols, i // cols
        x = -0.5 * (cols - 1) * 1.5 + 1.5 * c + rng.uniform(-0.2, 0.2)
        y = 2.0 + 1.5 * r + rng.uniform(0.0, 0.3)
        bodies.append(box(1.0, 1.0, x, y, angle=float(rng.uniform(-0.3, 0.3)), friction=friction))
    return _desc(f"Rain {n}", f"{n} boxes (1x1) rained into a {width:g} m open container", bodies)


def columns(n=1000, height=10, friction=0.6):
    """``n`` 1x1 boxes in free-standing columns of ``height`` (1.5 m apart) on one static ground:
    contacts per body stay constant as n grows (the scaling scene)."""
    ncol = max(1, math.ceil(n / height))
    span = 1.5 * ncol
    bodies = [box(span + 4.0, 1.0, 0.5 * span, -0.5, kind="static", friction=friction, name="ground")]
    for i in range(n):
        c, r = i // height, i % height
        bodies.append(box(1.0, 1.0, 1.5 * c + 0.75, 0.5 + r, friction=friction))
    return _desc(f"Columns {n}", f"{n} boxes in {ncol} columns of {height}", bodies)


def load_desc(path) -> dict:
    with open(path) as f:
        return json.load(f)


def with_world(desc, **world) -> dict:
    """A copy of ``desc`` with world fields overridden (gravity, dt, sleeping)."""
    d = copy.deepcopy(desc)
    d.setdefault("world", {}).update(world)
    return d


# -- shapes -----------------------------------------------------------------------
def shape_of(spec):
    """``physics`` shape for a scene-file shape spec."""
    import physics
    if "box" in spec:
        w, h = spec["box"]
        return physics.Polygon.box(float(w), float(h))
    if "polygon" in spec:
        return physics.Polygon(spec["polygon"])
    if "regular" in spec:
        r = spec["regular"]
        return physics.Polygon.regular(int(r["sides"]), float(r["radius"]))
    if "circle" in spec:
        c = spec["circle"]
        if isinstance(c, dict):
            return physics.Circle(float(c["radius"]), tuple(c.get("offset", (0.0, 0.0))))
        return physics.Circle(float(c))
    raise ValueError(f"unsupported shape spec {spec!r}")


def _friction(b):
    f = b.get("friction", 0.6)
    if isinstance(f, dict):
        return float(f.get("static", 0.6)), float(f.get("dynamic", f.get("static", 0.6)))
    if isinstance(f, (list, tuple)):
        return float(f[0]), float(f[1])
    return float(f), float(f)


def _bodies(desc):
    """Normalised body records: shape object, kind, pose, velocity, material."""
    out = []
    for b in desc["bodies"]:
        mu_s, mu_d = _friction(b)
        out.append(dict(name=b.get("name"), shape=shape_of(b["shape"]), kind=b.get("kind", "dynamic"),
                        position=tuple(map(float, b.get("position", (0.0, 0.0)))),
                        angle=float(b.get("angle", 0.0)),
                        velocity=tuple(map(float, b.get("velocity", (0.0, 0.0)))),
                        angular_velocity=float(b.get("angular_velocity", 0.0)),
                        density=float(b.get("density", 1.0)), restitution=float(b.get("restitution", 0.0)),
                        mu_s=mu_s, mu_d=mu_d))
    return out


# -- a common view of a running simulation ------------------------------------------
class Sim:
    """One engine running one scene: ``step()``, then read the state (centre-of-mass
    positions, angles, velocities) in the order of the description's bodies."""

    engine = ""

    def __init__(self, desc):
        self.desc = desc
        self.recs = _bodies(desc)
        self.dt = float(desc.get("world", {}).get("dt", 1 / 60))
        self.dynamic = np.array([r["kind"] == "dynamic" for r in self.recs])
        self.masses = np.array([r["shape"].mass_properties(r["density"])[0] for r in self.recs])

    def step(self):
        raise NotImplementedError

    def state(self):
        """(com (n,2), angle (n,), v (n,2), w (n,)) arrays."""
        raise NotImplementedError

    def origins(self):
        """Body-origin positions (the frame the description's vertices are in)."""
        com, ang, _, _ = self.state()
        out = np.empty_like(com)
        for i, r in enumerate(self.recs):
            c = r["shape"].centroid if hasattr(r["shape"], "centroid") else np.zeros(2)
            c = np.asarray(c, dtype=float)
            cs, sn = math.cos(ang[i]), math.sin(ang[i])
            out[i] = com[i] - (cs * c[0] - sn * c[1], sn * c[0] + cs * c[1])
        return out

    def kinetic_energy(self):
        _, _, v, w = self.state()
        inert = np.array([r["shape"].mass_properties(r["density"])[2] for r in self.recs])
        d = self.dynamic
        return float(0.5 * (self.masses[d] * (v[d] ** 2).sum(1) + inert[d] * w[d] ** 2).sum())

    def momentum(self):
        _, _, v, _ = self.state()
        d = self.dynamic
        return (self.masses[d, None] * v[d]).sum(0)


class OursSim(Sim):
    engine = "stelkropp"

    def __init__(self, desc, solver=None, settings=None, world=None, integrator=None, dt=None):
        super().__init__(desc)
        w = desc.get("world", {})
        if world is None:
            world = build_ours_world(desc)
        world.sleeping = bool(w.get("sleeping", False))
        if "gravity" in w:
            world.gravity = tuple(w["gravity"])
        if "dt" in w:
            world.dt = float(w["dt"])
        if solver:
            world.solver = solver
        if integrator:
            world.integrator = integrator
        for k, v in (settings or {}).items():
            world.settings[k] = v
        if dt:
            world.dt = dt
            self.dt = dt
        self.world = world
        self.handles = world.bodies

    def step(self):
        self.world.step()

    def state(self):
        w = self.world
        B = w._bodies.view
        n = w._bodies.n
        # slots follow insertion order while nothing is removed (the benchmark never removes)
        return B.x[:n].copy(), B.q[:n].copy(), B.v[:n].copy(), B.w[:n].copy()


def build_ours_world(desc):
    """A ``physics.World`` from a description (the scene loader's job, done here from the same dict
    so that benchmark-generated scenes need no file)."""
    import physics
    w = desc.get("world", {})
    world = physics.World(gravity=tuple(w.get("gravity", (0.0, -9.81))), dt=float(w.get("dt", 1 / 60)),
                          solver=w.get("solver", "soft_step"), integrator=w.get("integrator", "symplectic_euler"),
                          sleeping=bool(w.get("sleeping", True)), settings=w.get("settings") or None)
    handles = {}
    for i, (b, r) in enumerate(zip(desc["bodies"], _bodies(desc))):
        h = world.add_body(r["shape"], kind=r["kind"], position=r["position"], angle=r["angle"],
                           velocity=r["velocity"], angular_velocity=r["angular_velocity"], density=r["density"],
                           restitution=r["restitution"], friction=(r["mu_s"], r["mu_d"]))
        handles[b.get("name", i)] = h
    for s in desc.get("springs", []):
        world.add_spring(handles[s["a"]], None if s.get("b") is None else handles[s["b"]],
                         anchor_a=tuple(s.get("anchor_a", (0, 0))), anchor_b=tuple(s.get("anchor_b", (0, 0))),
                         stiffness=float(s.get("stiffness", 100.0)), damping=float(s.get("damping", 0.0)),
                         rest_length=s.get("rest_length"))
    return world


def _spring_ends(desc):
    names = {b.get("name", i): i for i, b in enumerate(desc["bodies"])}
    for s in desc.get("springs", []):
        yield (names[s["a"]], None if s.get("b") is None else names[s["b"]], tuple(s.get("anchor_a", (0, 0))),
               tuple(s.get("anchor_b", (0, 0))), float(s.get("stiffness", 100.0)), float(s.get("damping", 0.0)),
               s.get("rest_length"))


class PymunkSim(Sim):
    engine = "pymunk"

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
            if hasattr(shp, "vertices"):
                s = pymunk.Poly(body, [tuple(map(float, v)) for v in shp.vertices], radius=0.0)
            else:
                s = pymunk.Circle(body, float(shp.radius), tuple(map(float, shp.offset)))
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
        for a, b, la, lb, k, c, rest in _spring_ends(desc):
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

    def step(self):
        self.space.step(self.dt)

    def state(self):
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


class Box2DSim(Sim):
    engine = "pybox2d"

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
        for a, b, la, lb, k, c, rest in _spring_ends(desc):
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
        self.world.Step(self.dt, self.vi, self.pi)

    def state(self):
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


def build(engine, desc, **kw) -> Sim:
    """A ``Sim`` of ``desc`` in ``engine`` ("stelkropp", "pymunk", "pybox2d")."""
    if engine == "stelkropp":
        return OursSim(desc, **kw)
    if engine == "pymunk":
        return PymunkSim(desc, **kw)
    if engine == "pybox2d":
        return Box2DSim(desc, **kw)
    raise ValueError(f"unknown engine {engine!r}")


# -- engine-independent measures on poses -----------------------------------------------
def world_shapes(sim):
    """Per body: ('poly', world vertices) or ('circle', centre, radius) at the current pose."""
    org = sim.origins()
    _, ang, _, _ = sim.state()
    out = []
    for i, r in enumerate(sim.recs):
        c, s = math.cos(ang[i]), math.sin(ang[i])
        R = np.array([[c, -s], [s, c]])
        shp = r["shape"]
        if hasattr(shp, "vertices"):
            out.append(("poly", np.asarray(shp.vertices) @ R.T + org[i]))
        else:
            out.append(("circle", R @ np.asarray(shp.offset, float) + org[i], float(shp.radius)))
    return out


def _poly_depth(A, B):
    """Penetration depth of two convex CCW polygons by SAT (<= 0 when apart)."""
    best = np.inf
    for P, Q in ((A, B), (B, A)):
        e = np.roll(P, -1, 0) - P
        nrm = np.stack([e[:, 1], -e[:, 0]], 1)
        nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
        # overlap along each of P's face normals: face offset minus deepest point of Q
        face = np.einsum("ij,ij->i", nrm, P)
        deepest = (Q @ nrm.T).min(0)
        best = min(best, float((face - deepest).min()))
    return best


def _circle_poly_depth(c, r, P):
    e = np.roll(P, -1, 0) - P
    nrm = np.stack([e[:, 1], -e[:, 0]], 1)
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    sep = (c - P) @ nrm.T
    sep = np.einsum("ij,ij->i", c[None, :] - P, nrm)
    k = int(np.argmax(sep))
    if sep[k] > 0:
        # outside: distance to the closest point of the polygon's boundary
        t = np.clip(np.einsum("ij,ij->i", c - P, e) / np.einsum("ij,ij->i", e, e), 0, 1)
        d = np.linalg.norm(P + t[:, None] * e - c, axis=1).min()
        return r - d
    return r - sep[k]


def penetration(sim, include_static=True):
    """(max, mean over touching pairs) penetration depth of the current poses, measured by
    exact geometry the same way for every engine (ideal: zero)."""
    shapes = world_shapes(sim)
    n = len(shapes)
    ctr = np.empty((n, 2))
    rad = np.empty(n)
    for i, s in enumerate(shapes):
        if s[0] == "poly":
            ctr[i] = s[1].mean(0)
            rad[i] = np.linalg.norm(s[1] - ctr[i], axis=1).max()
        else:
            ctr[i], rad[i] = s[1], s[2]
    dyn = sim.dynamic
    order = np.argsort(ctr[:, 0])
    depths = []
    xs = ctr[order, 0]
    rmax = rad.max() if n else 0.0
    for a_i, a in enumerate(order):
        hi = np.searchsorted(xs, xs[a_i] + rad[a] + rmax, side="right")
        for b in order[a_i + 1:hi]:
            if not (dyn[a] or dyn[b]):
                continue
            if not include_static and not (dyn[a] and dyn[b]):
                continue
            if np.hypot(*(ctr[a] - ctr[b])) > rad[a] + rad[b]:
                continue
            sa, sb = shapes[a], shapes[b]
            if sa[0] == "poly" and sb[0] == "poly":
                d = _poly_depth(sa[1], sb[1])
            elif sa[0] == "circle" and sb[0] == "circle":
                d = sa[2] + sb[2] - float(np.hypot(*(sa[1] - sb[1])))
            elif sa[0] == "circle":
                d = _circle_poly_depth(sa[1], sa[2], sb[1])
            else:
                d = _circle_poly_depth(sb[1], sb[2], sa[1])
            if d > 0:
                depths.append(d)
    if not depths:
        return 0.0, 0.0
    return float(max(depths)), float(np.mean(depths))
