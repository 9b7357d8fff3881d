"""A suite scene's ``bench`` script run on Stelkropp's side, as bench/box2d/engine.py runs it on
Box2D's: ``events`` (bodies and joints added or removed before the step they name: the ragdoll
rain) and ``drives`` (a kinematic body steered to ``center + amplitude sin(omega t + phase)``:
the junkyard pusher), so that both engines are timed on the same work.

Events are checked and turned into (shape, fixture) lists once, before any timed step (Box2D's
side pre-translates them into shim records the same way); inside the timed loop only the bodies
and joints are created and removed through the world's public calls. A drive sets the velocity
that reaches the target pose in one step, as ``b2Body_SetTargetTransform`` does.
"""
from __future__ import annotations

import math

from .common import FORMAT, strip_box2d


def _checked(add, step):
    """(bodies, shapes, joints) of one event's ``add`` block, checked by the scene loader."""
    from physics.scene.checks import check
    data = strip_box2d({"format": FORMAT, "version": 2, "bodies": add.get("bodies", []),
                        "joints": add.get("joints", [])})
    if not data["joints"]:
        data.pop("joints")
    problems, shapes = check(data) if data["bodies"] else ([], [])
    if problems:
        raise ValueError(f"bench.events at step {step}: {problems[:3]}")
    return data["bodies"], shapes, data.get("joints", [])


def sleep_threshold(desc):
    """Box2D's per-body ``sleep_threshold`` when every dynamic body (events included) has the same
    one, else None: Stelkropp's is the world's ``sleep_linear``."""
    bodies = list(desc["bodies"])
    for e in desc.get("bench", {}).get("events", []):
        bodies += e.get("add", {}).get("bodies", [])
    got = {b.get("box2d", {}).get("sleep_threshold") for b in bodies if b.get("kind", "dynamic") == "dynamic"}
    return got.pop() if len(got) == 1 and None not in got else None


class Scripted:
    """``sim`` (an OursSim) with the description's ``bench.events`` and ``bench.drives`` applied
    before the step they name; ``step`` counts from 0 as Box2D's side does."""

    def __init__(self, sim, desc):
        self.sim, self.world, self.steps = sim, sim.world, 0
        bench = desc.get("bench", {})
        self.events = {}
        for e in bench.get("events", []):
            k = int(e["step"])
            self.events.setdefault(k, []).append((list(e.get("remove", [])), *_checked(e.get("add", {}), k)))
        self.drives = []
        for d in bench.get("drives", []):
            b = self.world.body(d["body"])
            self.drives.append((b, d.get("center", b.position), d["amplitude"], float(d["omega"]),
                                float(d.get("phase", 0.0)), b.angle))

    def _apply(self, removes, bodies, shapes, joints):
        from physics.scene.joints import add_joints
        from physics.scene.load import _add_body
        from physics.scene.problems import scene_error
        w = self.world
        for name in removes:
            w.remove(w.body(name))
        made = [_add_body(w, b, s, f"bench.events.bodies[{i}]", "bench.events") for i, (b, s) in
                enumerate(zip(bodies, shapes))]
        by_name = {b["name"]: h for b, h in zip(bodies, made) if "name" in b}
        add_joints(w, joints, by_name, scene_error, "bench.events")

    def _drive(self, k):
        dt = self.world.dt
        t = k * dt
        for b, c, amp, om, ph, ang in self.drives:
            s = math.sin(om * t + ph)
            x, y = b.position
            b.velocity = ((c[0] + amp[0] * s - x) / dt, (c[1] + amp[1] * s - y) / dt)
            b.angular_velocity = (ang - b.angle) / dt

    def before(self, k):
        """The events and drives of step ``k`` (counted from 0)."""
        for ev in self.events.get(k, ()):
            self._apply(*ev)
        if self.drives:
            self._drive(k)

    def step(self):
        """The events and drives of this step, then one world step."""
        self.before(self.steps)
        self.sim.step()
        self.steps += 1

    def __getattr__(self, name):  # state(), origins(), recs ... of the wrapped sim
        return getattr(self.sim, name)
