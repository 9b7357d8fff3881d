"""World's joints: adding, editing and removing them, names (a part of World).

``add_joint(kind, body_a, body_b, **parameters)`` takes issue 14's keywords
(physics/joint_params.py lists them per kind).  Anchors and axes are given in
world coordinates at creation and stored in each body's frame relative to its
centre of mass; ``local_anchor_a``/``local_anchor_b``/``local_axis``/
``reference_angle`` give the stored values exactly instead (scene files use
them, so a saved joint reloads bit for bit).  Removing a body removes its joints.
"""
from __future__ import annotations

import math

import numpy as np

from . import joint_params as jp
from .body import Body
from .joint import Joint
from .joint_kinds import CLASS_OF
from .store.joints import BROKEN, COLLIDE, JOINT_KINDS
from .validate import finite_num, finite_vec


def _unrot(q, v):
    c, s = math.cos(q), math.sin(q)
    return np.array([c * v[0] + s * v[1], -s * v[0] + c * v[1]])


def _unit(v, field):
    n = math.hypot(v[0], v[1])
    if not n > 1e-12:
        raise ValueError(f"{field}: must be a non-zero direction, got {tuple(v)!r}")
    # a unit vector is kept as it is, so a saved axis reloads exactly
    return np.array(v, dtype=np.float64) if abs(n - 1.0) <= 1e-12 else np.asarray(v) / n


class JointsMixin:
    """The joint part of :class:`~physics.World` (see world.py for the state it uses)."""

    @property
    def _joints(self):
        return self._store.joints

    def add_joint(self, kind: str, body_a: Body, body_b: Body | None = None, **parameters) -> Joint:
        """Join ``body_a`` to ``body_b`` (None: to the world) with a joint of ``kind`` (one of
        physics/joint_params.py's ``KINDS``: revolute, prismatic, weld, distance, wheel, rotary,
        motor, mouse).  Keywords: the kind's parameters (physics/joint_params.py), its geometry (anchor/axis in world coordinates, or
        local_anchor_a/local_anchor_b/local_axis/reference_angle), name, collide_connected,
        break_force, break_torque.  ValueError names a bad field; TypeError an unknown keyword.

        Returns the handle, an instance of the kind's class (``physics.RevoluteJoint``, ...,
        subclasses of ``physics.Joint``); calling that class, ``physics.RevoluteJoint(body_a,
        body_b, ...)``, is the same call on body_a's world."""
        return self._add_joint(kind, body_a, body_b, parameters, "add_joint")

    def _add_joint(self, kind, body_a, body_b, parameters: dict, caller: str) -> Joint:
        """add_joint's work; ``caller`` (add_joint or a kind's class) opens the TypeError's message."""
        self._check_editable("add_joint")
        if not isinstance(kind, str) or kind not in JOINT_KINDS:
            raise ValueError(f"kind: must be one of {list(JOINT_KINDS)}, got {kind!r}")
        self._check_bodies(kind, body_a, body_b)
        allowed = set(jp.PARAMS[kind]) | set(jp.GEOMETRY[kind]) | set(jp.COMMON)
        unknown = sorted(set(parameters) - allowed)
        if unknown:
            raise TypeError(f"{caller}: a {kind} joint takes no {', '.join(map(repr, unknown))}; it takes "
                            f"{', '.join(sorted(allowed))}")
        values = {}
        for name, p in jp.PARAMS[kind].items():
            if name == "target" and parameters.get(name) is None:
                values[name] = np.array(body_a.center_of_mass)
            else:
                values[name] = jp.check(name, p.rule, parameters.get(name, p.default))
        jp.ordered(kind, values)
        geo = self._joint_geometry(kind, body_a, body_b, parameters, values)
        collide = parameters.get("collide_connected", False)
        if not isinstance(collide, (bool, np.bool_)):
            raise ValueError(f"collide_connected: must be true or false, got {collide!r}")
        bf = jp.breaking("break_force", parameters.get("break_force"))
        bt = jp.breaking("break_torque", parameters.get("break_torque"))
        name = parameters.get("name")
        if name is not None:
            self._joint_names.check_new(name)
        oid, s = self._joints.add()
        J = self._joints.view
        J.kind[s] = JOINT_KINDS.index(kind)
        J.a[s] = body_a._s
        J.b[s] = -1 if body_b is None else body_b._s
        for key, v in geo.items():
            getattr(J, key)[s] = v
        for pname, p in jp.PARAMS[kind].items():
            v = values[pname]
            if p.field not in geo:
                getattr(J, p.field)[s] = np.nan if v is None else v
        J.flags[s] = COLLIDE if collide else 0
        J.break_force[s] = np.nan if bf is None else bf
        J.break_torque[s] = np.nan if bt is None else bt
        h = CLASS_OF[kind]._handle(self, oid, body_a, body_b)
        self._joint_handles[oid] = h
        self._joint_names.add(oid, name)
        self._joint_edited(h, structural=True)
        return h

    def _check_bodies(self, kind, body_a, body_b):
        for b, field in ((body_a, "body_a"), (body_b, "body_b")):
            if b is None and field == "body_b":
                continue
            if not isinstance(b, Body) or b.world is not self or not b.alive:
                raise ValueError(f"{field}: expected a live body of this world, got {b!r}")
        if body_a is body_b:
            raise ValueError("body_b: a joint needs two different bodies (or None for the world)")
        if kind == "mouse" and body_b is not None:
            raise ValueError("body_b: a mouse joint pulls body_a towards a world target; pass None")

    def _local_point(self, body, p):
        """A world point in ``body``'s frame relative to its centre of mass (or as is for the world)."""
        if body is None:
            return np.array(p, dtype=np.float64)
        s = body._s
        B = self._bodies.view
        return _unrot(float(B.q[s]), p - B.x[s])

    def _given_local(self, body, v, field):
        v = finite_vec(v, field)
        return v if body is None else v - self._bodies.view.com[body._s]

    def _joint_geometry(self, kind, a, b, kw, values) -> dict:
        """The table's geometry fields for a new joint (see the module doc)."""
        B = self._bodies.view
        qa = float(B.q[a._s])
        qb = 0.0 if b is None else float(B.q[b._s])
        geo = {}
        decl = jp.KINDS[kind]
        if "anchor" in decl.geometry or "anchor_a" in decl.geometry:
            if "anchor_a" in decl.geometry:
                pa = finite_vec(kw.get("anchor_a", a.position), "anchor_a")
                pb = finite_vec(kw.get("anchor_b", (0.0, 0.0) if b is None else b.position), "anchor_b")
            else:
                pa = pb = finite_vec(kw.get("anchor", a.position), "anchor")
            la = (self._given_local(a, kw["local_anchor_a"], "local_anchor_a") if "local_anchor_a" in kw
                  else self._local_point(a, pa))
            lb = (self._given_local(b, kw["local_anchor_b"], "local_anchor_b") if "local_anchor_b" in kw
                  else self._local_point(b, pb))
            geo["la"], geo["lb"] = la, lb
        if "reference_angle" in decl.readouts:
            geo["ref"] = finite_num(kw.get("reference_angle", qa - qb), "reference_angle")
        if decl.axis is not None:
            if "local_axis" in kw:
                geo["axis"] = _unit(finite_vec(kw["local_axis"], "local_axis"), "local_axis")
            else:
                geo["axis"] = _unit(_unrot(qa, finite_vec(kw.get("axis", decl.axis), "axis")), "axis")
        if kind == "distance" and values["length"] is None:
            pa = B.x[a._s] + _unrot(-qa, geo["la"])
            pb = geo["lb"] if b is None else B.x[b._s] + _unrot(-qb, geo["lb"])
            values["length"] = float(np.hypot(*(pa - pb)))
        if kind == "motor":
            geo["la"] = -B.com[a._s]
            geo["lb"] = self._given_local(b, values["linear_offset"], "linear_offset")
        if kind == "mouse":
            target = values["target"]
            geo["la"] = (self._given_local(a, kw["local_anchor_a"], "local_anchor_a") if "local_anchor_a" in kw
                         else self._local_point(a, target))
            geo["lb"] = target
        return geo

    # -- edits -------------------------------------------------------------------
    def _joint_edited(self, joint: Joint, structural: bool = False) -> None:
        """A joint changed: wake its bodies; ``structural``: its rows or collision filter changed."""
        self._touched(joint.body_a._s)
        if joint.body_b is not None:
            self._touched(joint.body_b._s)
        if structural:
            self._joints.edited(joint._s)
        self._pipeline.invalidate()

    def _set_joint_anchor(self, joint: Joint, side: str, p) -> None:
        body = joint.body_a if side == "a" else joint.body_b
        (self._joints.view.la if side == "a" else self._joints.view.lb)[joint._s] = self._local_point(body, p)
        self._joint_edited(joint)

    def _set_joint_axis(self, joint: Joint, v, local: bool) -> None:
        u = _unit(v if local else _unrot(joint.body_a.angle, v), "local_axis" if local else "axis")
        self._joints.view.axis[joint._s] = u
        self._joint_edited(joint)

    def _set_joint_point(self, joint: Joint, name: str, v) -> None:
        """A mouse joint's target or a motor joint's linear offset."""
        s = joint._s
        J = self._joints.view
        if name == "linear_offset":
            J.offset[s] = v
            J.lb[s] = self._given_local(joint.body_b, v, "linear_offset")
        else:
            J.lb[s] = v
        self._joint_edited(joint)

    def _break_joint(self, joint: Joint) -> None:
        """Mark ``joint`` broken, as if it had broken in an earlier step (the loader: a saved broken
        joint stays broken and is not reported by broken_joints() again)."""
        s = joint._s
        self._joints.view.flags[s] |= BROKEN
        self._joints._reported.add(joint.id)
        self._joints.edited(s)
        self._pipeline.invalidate()

    # -- removal and lookup ----------------------------------------------------------
    def remove(self, item) -> None:
        """Remove a joint, a spring, or a body (and the joints and springs attached to it)."""
        self._check_editable("remove")
        if isinstance(item, Joint):
            self._remove_joint(item)
            return
        if isinstance(item, Body) and item.world is self and item.alive:
            for oid in self._joint_ids_on(item._s):
                self._remove_joint(self._joint_handles[oid])
            s, last = item._s, self._bodies.n - 1
            super().remove(item)
            if s != last:
                self._joints.remap_removed_body(s, last)
            return
        super().remove(item)

    def _joint_ids_on(self, s: int) -> list[int]:
        """Ids of the joints on body slot ``s``, in creation order (the handles' order): the
        table's columns find them without a pass over every handle (rain removes 275 bodies
        among 10,000 joints per event), and the order matters, since each removal renumbers."""
        n = self._joints.n
        J = self._joints.view
        hit = (J.a[:n] == s) | (J.b[:n] == s)
        return sorted(int(i) for i in J.id[:n][hit])

    def _remove_joint(self, joint: Joint) -> None:
        if not isinstance(joint, Joint) or joint._world is not self or not joint.alive:
            raise ValueError(f"remove: {joint!r} is not a live joint of this world")
        for body in (joint.body_a, joint.body_b):
            if body is not None and body.alive:
                self._touched(body._s)
        self._joints.remove(joint.id)
        del self._joint_handles[joint.id]
        self._joint_names.drop(joint.id)
        self._pipeline.invalidate()

    def joint(self, name: str) -> Joint:
        """The joint called ``name`` (KeyError if there is none)."""
        return self._joint_handles[self._joint_names.id_of(name)]

    @property
    def joints(self) -> list[Joint]:
        """Every joint of the world (broken ones included), in table order."""
        ids = self._joints.view.id[: self._joints.n]
        return [self._joint_handles[int(i)] for i in ids]

    @property
    def broken_joints(self) -> list[Joint]:
        """The joints that broke in the last step."""
        return [self._joint_handles[i] for i in self._joints.broken_last_step if i in self._joint_handles]

