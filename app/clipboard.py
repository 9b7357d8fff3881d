"""Copy and paste of bodies (and the springs and joints among them): Ctrl+C keeps their specs,
Ctrl+V adds a copy with the copied group's centre at the pointer (one undoable step); Ctrl+D
duplicates the same way, beside the originals."""
from __future__ import annotations

import numpy as np

import physics

from .commands import SPRING_FIELDS, AddBody, AddJoint, AddSpring, Command, body_spec
from .copy_names import copy_name, world_names
from .joint_specs import joint_fields, moved_world_anchor

NUDGE = np.array([0.6, -0.6])     # a paste where the originals are goes beside them, not on top


def copy_bodies(world, bodies, tool_springs=(), tool_joints=()):
    """The clipboard for ``bodies``: their specs, the springs and joints between them or to the
    world (not the tools' own: the mouse joint), and their centre (mean position, m)."""
    index = {b.id: k for k, b in enumerate(bodies)}
    springs = []
    for sp in world.springs:
        if sp.id in tool_springs or sp.body_a.id not in index:
            continue
        if sp.body_b is not None and sp.body_b.id not in index:
            continue
        springs.append((index[sp.body_a.id], None if sp.body_b is None else index[sp.body_b.id],
                        {f: getattr(sp, f) for f in SPRING_FIELDS}))
    joints = []
    for j in world.joints:
        if j.id in tool_joints or j.body_a.id not in index or (j.body_b is not None and j.body_b.id not in index):
            continue
        joints.append((j.kind, index[j.body_a.id], None if j.body_b is None else index[j.body_b.id],
                       joint_fields(j)))
    centre = np.mean([b.position for b in bodies], axis=0)
    return {"bodies": [body_spec(b) for b in bodies], "springs": springs, "joints": joints, "centre": centre}


class Paste(Command):
    """Add the clipboard's bodies moved by ``offset`` (m) and their springs and joints (world
    anchors moved too); a named original gives a copy named "<name> copy" (names stay unique:
    ``copy_names``), chosen at the first paste and kept by a redo."""

    def __init__(self, clip, offset, verb="paste"):
        off = np.asarray(offset, dtype=np.float64)
        self.adds = []
        for spec in clip["bodies"]:
            spec = dict(spec, position=tuple(np.asarray(spec["position"]) + off))
            self.adds.append(AddBody(spec, verb))
        self.spring_specs = []
        for ia, ib, fields in clip["springs"]:
            f = dict(fields)
            if ib is None:
                f["anchor_b"] = tuple(np.asarray(f["anchor_b"]) + off)
            self.spring_specs.append((ia, ib, f))
        self.joint_specs = [(kind, ia, ib, dict(moved_world_anchor(kind, f, off) if ib is None else f))
                            for kind, ia, ib, f in clip.get("joints", ())]
        self.named = False
        self.spring_cmds = None
        self.joint_cmds = None
        self.label = f"{verb} {len(self.adds)} bod{'y' if len(self.adds) == 1 else 'ies'}"

    def name_copies(self, world):
        """Free names for the copies (once: a redo makes the same ones again)."""
        taken = world_names(world)
        for c in self.adds:
            c.spec["name"] = copy_name(c.spec.get("name"), taken)
        for _, _, f in self.spring_specs + [(a, b, f) for _, a, b, f in self.joint_specs]:
            f["name"] = copy_name(f.get("name"), taken)
        self.named = True

    def do(self, app):
        if not self.named:
            self.name_copies(app.world)
        for c in self.adds:
            c.do(app)
        if self.spring_cmds is None:
            self.spring_cmds = [AddSpring({"a": self.adds[ia].ref, "b": None if ib is None else self.adds[ib].ref,
                                           **f}) for ia, ib, f in self.spring_specs]
        for c in self.spring_cmds:
            c.do(app)
        if self.joint_cmds is None:
            self.joint_cmds = [AddJoint({"kind": kind, "a": self.adds[ia].ref,
                                         "b": None if ib is None else self.adds[ib].ref, "fields": f})
                               for kind, ia, ib, f in self.joint_specs]
        for c in self.joint_cmds:
            c.do(app)

    def undo(self, app):
        for c in reversed(self.joint_cmds or []):
            c.undo(app)
        for c in reversed(self.spring_cmds or []):
            c.undo(app)
        for c in reversed(self.adds):
            c.undo(app)

    def bodies(self):
        return [c.ref.obj for c in self.adds]


def paste_offset(clip, at):
    """Where a paste goes: the clipboard's centre at world point ``at``, nudged aside if that is
    where the originals are."""
    off = np.asarray(at, dtype=np.float64) - clip["centre"]
    return NUDGE if np.hypot(*off) < 0.05 else off


def selected_bodies(selection):
    return [s for s in selection if isinstance(s, physics.Body) and s.alive]
