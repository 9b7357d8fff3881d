"""``Box2DV3Sim``: Box2D v3 itself running a bench scene description, behind the bench's ``Sim``.

    sim = Box2DV3Sim(desc, threads=1, substeps=4, sleeping=False)
    for _ in range(600):
        sim.step()
    com, angle, v, w = sim.state()

The description is a Stelkropp scene dict (version 1, or version 2 with ``shapes`` and
``joints``; translation rules in ``scene.py``, ``shapes.py``, ``joints.py``). Bench scripts ride
along under ``desc["bench"]``: ``events`` (bodies and joints added or removed before a given
step: the rain benchmark's ragdolls) and ``drives`` (kinematic bodies steered to a target pose
each step with ``b2Body_SetTargetTransform``: the junkyard pusher). Body arrays follow the
description's body order, then bodies added by events in creation order (removed ones read NaN).
"""
from __future__ import annotations

import itertools
import math

import numpy as np

from ..desc import body_records
from ..engines.base import Sim
from . import lib as L
from .scene import bodies_records, joints_records, springs_records, world_params

ENGINE = "box2d_v3"


def _flat(records):
    return np.fromiter(itertools.chain.from_iterable(records), dtype=np.float64)


class Box2DV3Sim(Sim):
    """One Box2D v3 world built from ``desc``; the ``Sim`` interface of bench/engines/base.py.

    threads: Box2D workers (1 = serial); scheduler: "shim" (our pthread task system behind
    ``enqueueTask``/``finishTask``) or "box2d" (Box2D's built-in one, as its benchmark app uses);
    substeps: Box2D sub-steps per step (None: ``world.settings.substeps``, else 4); sleeping:
    False/True, or None for the description's ``world.sleeping`` (the format's default: True);
    track_angles: unwrap body angles across +-pi after every step (off only for timing runs).
    Raises ``BuildError`` without Box2D, ``ValueError`` naming the field for a bad description.
    """

    engine = ENGINE
    settings_label = "4 sub-steps, 1 thread"  # the bench's defaults (an instance says its own)

    def __init__(self, desc, threads=1, substeps=4, sleeping=False, scheduler="shim", track_angles=True,
                 box2d_src=None):
        self.lib = L.load(box2d_src)
        self.desc = desc
        w = desc.get("world", {})
        self.dt = float(w.get("dt", 1 / 60))
        if substeps is None:
            substeps = int((w.get("settings") or {}).get("substeps", 4))
        self.substeps, self.threads, self.scheduler = int(substeps), int(threads), scheduler
        self.settings_label = f"{self.substeps} sub-steps, {self.threads} thread(s)"
        p = np.array(world_params(desc, sleeping, self.threads, scheduler, track_angles))
        self._w = self.lib.s2_world_create(L.as_ptr(p), len(p))
        if not self._w:
            raise RuntimeError("s2_world_create failed")
        self.names = {}
        self._kinds = [b.get("kind", "dynamic") for b in desc.get("bodies", [])]
        self._exec(bodies_records(desc.get("bodies", []), 0, self.names))
        self.n_desc = self.lib.s2_body_count(self._w)
        self._refresh_mass()
        self.joint_names, self.joint_kinds, self._breaks = [], [], {}
        self._exec(springs_records(desc.get("springs", []), self.names, self._mass[:, 0]))
        self.joint_names += [s.get("name") for s in desc.get("springs", [])]
        self.joint_kinds += ["spring"] * len(desc.get("springs", []))
        self._add_joints(desc.get("joints", []), "joints")
        self.broken = []
        self._compile_bench(desc.get("bench", {}))
        self.steps = 0

    # -- building -------------------------------------------------------------------------
    def _exec(self, records):
        if not records:
            return 0
        buf = _flat(records)
        out = np.zeros(len(records), dtype=np.int32)
        made = self.lib.s2_exec(self._w, L.as_ptr(buf), len(buf), L.as_ptr(out), len(out))
        if made < 0:
            raise ValueError(f"Box2D shim rejected a record: {self.lib.s2_error(self._w).decode()}")
        return made

    def _add_joints(self, joints, path):
        recs, kinds = joints_records(joints, self.names, path)
        first = len(self.joint_names)
        self._exec(recs)
        for i, (j, k) in enumerate(zip(joints, kinds)):
            self.joint_names.append(j.get("name"))
            self.joint_kinds.append(k)
            if j.get("break_force") is not None or j.get("break_torque") is not None:
                self._breaks[first + i] = (j.get("break_force"), j.get("break_torque"))

    def _compile_bench(self, bench):
        """Pre-translate the events (outside any timed loop): slots are assigned in order."""
        self.events = {}
        slot = self.n_desc
        for e in bench.get("events", []):
            recs = []
            for name in e.get("remove", []):
                if name not in self.names:
                    raise ValueError(f"bench.events: remove names unknown body {name!r}")
                recs.append([L.OP_DESTROY_BODY, self.names.pop(name)[0]])
            bodies = e.get("add", {}).get("bodies", [])
            recs += bodies_records(bodies, slot, self.names, "bench.events.add.bodies")
            self._kinds += [b.get("kind", "dynamic") for b in bodies]
            slot += len(bodies)
            jrecs, kinds = joints_records(e.get("add", {}).get("joints", []), self.names, "bench.events.add.joints")
            self.joint_names += [j.get("name") for j in e.get("add", {}).get("joints", [])]
            self.joint_kinds += kinds
            buf = _flat(recs + jrecs)
            self.events.setdefault(int(e["step"]), []).append((buf, len(recs) + len(jrecs)))
        self.drives = []
        for d in bench.get("drives", []):
            if d.get("body") not in self.names:
                raise ValueError(f"bench.drives: no body named {d.get('body')!r}")
            s, (pos, ang) = self.names[d["body"]]
            self.drives.append((s, np.array(d.get("center", pos), float), np.array(d["amplitude"], float),
                                float(d["omega"]), float(d.get("phase", 0.0)), ang))

    def _refresh_mass(self):
        n = self.lib.s2_body_count(self._w)
        m = np.zeros((n, L.MASS_READ))
        self.lib.s2_read_mass(self._w, L.as_ptr(m), n)
        self._mass = m
        self.dynamic = np.array([k == "dynamic" for k in self._kinds[:n]], dtype=bool)
        self.masses = np.nan_to_num(m[:, 0])

    # -- stepping ---------------------------------------------------------------------------
    def _before(self, k):
        for buf, count in self.events.get(k, ()):
            out = np.zeros(max(count, 1), dtype=np.int32)
            if self.lib.s2_exec(self._w, L.as_ptr(buf), len(buf), L.as_ptr(out), len(out)) < 0:
                raise ValueError(f"bench event at step {k}: {self.lib.s2_error(self._w).decode()}")
        t = k * self.dt
        for s, c, amp, om, ph, ang in self.drives:
            x, y = c + amp * math.sin(om * t + ph)
            self.lib.s2_set_target(self._w, s, x, y, ang, self.dt)

    def step(self):
        """Advance one step of ``dt`` (events and drives of this step applied first)."""
        if self.events or self.drives:
            self._before(self.steps)
        self.lib.s2_step(self._w, self.dt, self.substeps, 1)
        self.steps += 1
        if self._breaks:
            self._check_breaks()

    def run(self, n):
        """``n`` steps; one C call when the scene has no events, drives or breakable joints."""
        if self.events or self.drives or self._breaks:
            for _ in range(n):
                self.step()
        else:
            self.lib.s2_step(self._w, self.dt, self.substeps, int(n))
            self.steps += int(n)

    def _check_breaks(self):
        r = self.joint_readouts()
        for j, (fmax, tmax) in list(self._breaks.items()):
            f = math.hypot(r["force"][j, 0], r["force"][j, 1])
            if (fmax is not None and f > fmax) or (tmax is not None and abs(r["torque"][j]) > tmax):
                buf = np.array([L.OP_DESTROY_JOINT, j], float)
                self.lib.s2_exec(self._w, L.as_ptr(buf), 2, L.as_ptr(np.zeros(1, np.int32)), 1)
                del self._breaks[j]
                self.broken.append(j)

    # -- reading ------------------------------------------------------------------------------
    def _bodies(self):
        n = self.lib.s2_body_count(self._w)
        out = np.empty((n, L.BODY_READ))
        self.lib.s2_read_bodies(self._w, L.as_ptr(out), n)
        return out

    def snapshot(self):
        """(n, 10) per body: origin x, y, angle, vx, vy, w, com x, y, valid, awake (one C call)."""
        return self._bodies()

    def state(self):
        """(com (n,2), angle (n,), v (n,2), w (n,)): centre of mass, unwrapped angle, velocities."""
        b = self._bodies()
        return b[:, 6:8].copy(), b[:, 2].copy(), b[:, 3:5].copy(), b[:, 5].copy()

    def origins(self):
        """Body-origin positions (the frame of the description's vertices)."""
        return self._bodies()[:, 0:2].copy()

    def awake(self):
        """Per body: True while awake (sleeping enabled), NaN rows of removed bodies False."""
        return self._bodies()[:, 9] > 0

    def kinetic_energy(self):
        """Total kinetic energy (J) of the dynamic bodies, with Box2D's masses and inertias."""
        if len(self._mass) != self.lib.s2_body_count(self._w):
            self._refresh_mass()  # events added bodies since
        _, _, v, w = self.state()
        d = self.dynamic & np.isfinite(w)
        m, inert = self._mass[:, 0], self._mass[:, 1]
        return float(0.5 * (m[d] * (v[d] ** 2).sum(1) + inert[d] * w[d] ** 2).sum())

    def mass_data(self):
        """(n, 4): mass (kg), inertia about the centre of mass (kg m^2), local centre x, y."""
        self._refresh_mass()
        return self._mass.copy()

    def joint_readouts(self):
        """Per joint slot: force (n,2) N and torque (n,) N m on body B of the last step, linear and
        angular separation (m, rad), value (revolute angle / prismatic translation / distance length),
        rate, motor torque or force, valid (False once destroyed or broken)."""
        n = self.lib.s2_joint_count(self._w)
        o = np.empty((n, L.JOINT_READ))
        self.lib.s2_read_joints(self._w, L.as_ptr(o), n)
        return {"force": o[:, 0:2], "torque": o[:, 2], "linear_separation": o[:, 3],
                "angular_separation": o[:, 4], "value": o[:, 5], "rate": o[:, 6], "motor": o[:, 7],
                "valid": o[:, 8] > 0}

    def counters(self):
        """Box2D's counters: bodies, shapes, contacts, joints, islands, awake bodies, touching contacts."""
        out = np.zeros(L.COUNTERS, dtype=np.int32)
        self.lib.s2_counters(self._w, L.as_ptr(out))
        keys = ("bodies", "shapes", "contacts", "joints", "islands", "awake_bodies", "touching_contacts")
        return dict(zip(keys, map(int, out)))

    def slot(self, name):
        """The body slot (index into the state arrays) of a named body."""
        return self.names[name][0]

    def set_mouse_target(self, joint, target):
        """Move a mouse joint's target (world point); ``joint`` is its name or slot."""
        j = self.joint_names.index(joint) if isinstance(joint, str) else int(joint)
        self.lib.s2_set_frame_a(self._w, j, float(target[0]), float(target[1]), 0.0)

    def last_step_ms(self):
        """Box2D's own profile of the last step (ms)."""
        return float(self.lib.s2_last_step_ms(self._w))

    @property
    def recs(self):
        """bench/desc.py's per-body records (physics shapes), for version-1 descriptions only."""
        if getattr(self, "_recs", None) is None:
            self._recs = body_records(self.desc)
        return self._recs

    def close(self):
        """Destroy the Box2D world (also done when the Sim is garbage collected)."""
        if getattr(self, "_w", None):
            self.lib.s2_world_destroy(self._w)
            self._w = None

    def __del__(self):
        self.close()
