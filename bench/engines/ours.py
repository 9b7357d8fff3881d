"""Stelkropp behind the ``Sim`` interface: a ``physics.World`` built from a description."""
from __future__ import annotations

import numpy as np

from ..desc import body_records
from .base import Sim
from .ours_joints import readouts


class OursSim(Sim):
    """Stelkropp running a description.  ``solver`` / ``settings`` / ``integrator`` choose the
    mode and override its defaults; ``world``: an already built world of the same bodies (the
    scene loader's), else one is built from the description; ``dt`` (s) overrides the
    description's; ``threads``: World.threads (1 unless asked: the figures compare one thread
    with one).  Sleeping, gravity and dt follow the description's world block."""

    engine = "stelkropp"

    def __init__(self, desc, solver=None, settings=None, world=None, integrator=None, dt=None, threads=1):
        super().__init__(desc)
        w = desc.get("world", {})
        if world is None:
            world = build_ours_world(desc)
        world.sleeping = bool(w.get("sleeping", False))
        world.threads = threads
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
        # body-frame centre of mass of every body: state() turns the origins back into centres
        self._local_com = np.array([r["shape"].centroid for r in self.recs], float).reshape(-1, 2)

    def step(self):
        """One ``world.step()``."""
        self.world.step()

    def joint_readouts(self):
        """Per joint slot (springs, then joints): force (n,2) N and torque (n,) N m, linear and
        angular separation (m, rad), value, rate, motor, valid, as ``Box2DV3Sim.joint_readouts``
        reports them (bench/engines/ours_joints.py)."""
        return readouts(self.world)

    def state(self):
        """(com, angle, v, w) from ``world.state()`` (body order = description order: the
        benchmark never removes bodies)."""
        s = self.world.state()
        q = s["angle"]
        c, sn = np.cos(q), np.sin(q)
        lc = self._local_com
        com = s["position"].copy()
        if np.any(lc):
            com[:, 0] += c * lc[:, 0] - sn * lc[:, 1]
            com[:, 1] += sn * lc[:, 0] + c * lc[:, 1]
        return com, q.copy(), s["velocity"].copy(), s["angular_velocity"].copy()


def build_ours_world(desc):
    """A ``physics.World`` from a description (the scene loader's job, done here from the same dict
    so that benchmark-generated scenes need no file)."""
    import physics
    w = desc.get("world", {})
    world = physics.World(gravity=tuple(w.get("gravity", (0.0, -9.81))), dt=float(w.get("dt", 1 / 60)),
                          solver=w.get("solver", "soft_step"), integrator=w.get("integrator", "symplectic_euler"),
                          sleeping=bool(w.get("sleeping", True)), settings=w.get("settings") or None)
    handles = {}
    for i, (b, r) in enumerate(zip(desc["bodies"], body_records(desc))):
        handles[b.get("name", i)] = _add_record(world, r)
    for s in desc.get("springs", []):
        world.add_spring(handles[s["a"]], None if s.get("b") is None else handles[s["b"]],
                         anchor_a=tuple(s.get("anchor_a", (0, 0))), anchor_b=tuple(s.get("anchor_b", (0, 0))),
                         stiffness=float(s.get("stiffness", 100.0)), damping=float(s.get("damping", 0.0)),
                         rest_length=s.get("rest_length"))
    for j in desc.get("joints", []):
        _add_joint(world, j, handles)
    return world


def _add_joint(world, j, handles):
    """One scene-format joint (its keys are ``World.add_joint``'s keywords; Box2D-only ``box2d``
    tuning is not Stelkropp's and is left out)."""
    kw = {k: tuple(v) if isinstance(v, list) else v for k, v in j.items() if k not in ("kind", "a", "b", "box2d")}
    b = j.get("b")
    return world.add_joint(j["kind"], handles[j["a"]], None if b is None else handles[b], **kw)


def _add_record(world, r):
    """One body from a normalised record (bench/desc.py ``body_records``): its one shape, or every
    fixture of its ``parts`` (several shapes, a chain's segments, a capsule, a rounded box) with
    each part's own density, friction and restitution, as the scene loader builds it."""
    pose = dict(kind=r["kind"], position=r["position"], angle=r["angle"], velocity=r["velocity"],
                angular_velocity=r["angular_velocity"])
    if not r["parts"]:
        return world.add_body(r["shape"], **pose, density=r["density"], restitution=r["restitution"],
                              friction=(r["mu_s"], r["mu_d"]))
    (first, m), rest = r["parts"][0], r["parts"][1:]
    body = world.add_body(first, **pose, density=m["density"], restitution=m["restitution"],
                          friction=(m["mu_s"], m["mu_d"]))
    with world._placing_once():  # add_fixture keeps the body origin; mass and centre follow, once
        for shape, m in rest:
            body.add_fixture(shape, density=m["density"], friction=(m["mu_s"], m["mu_d"]),
                             restitution=m["restitution"])
    return body


def scene_world(desc, source=None):
    """The world the scene loader (``physics.scene.scene_from_dict``) builds from a bench suite
    description: its real shapes (segments, capsules, rounded polygons, several per body) and
    joints; the Box2D-only ``box2d`` keys and the bench's ``bench`` script are dropped first.
    SceneError when the loader refuses it (never a stand-in scene)."""
    from physics.scene import scene_from_dict

    from ..suite.common import strip_box2d
    data = strip_box2d(desc)
    data.pop("bench", None)
    return scene_from_dict(data, source=source or f"bench description {desc.get('name')!r}")


def loaded_world(data, source):
    """The world the scene loader builds from a shipped scene's raw description ``data``, or
    None when the loader refuses it (the benchmark then builds from the description itself)."""
    try:
        from physics.scene import scene_from_dict
        world = scene_from_dict(data, source=source)
    except Exception:  # the loader is another module's job; the same dict builds the same world
        return None
    return world if len(world.bodies) == len(data["bodies"]) else None
