"""The open scene: its world, file path, loaded snapshot (for reset), undo history, dirty flag."""
from __future__ import annotations

from pathlib import Path

import physics

from .commands import SPRING_FIELDS, History, Refs
from .fixture_specs import body_spec, make_body
from .joint_specs import joint_fields, make_joint

WORLD_FIELDS = ("gravity", "dt", "integrator", "broadphase", "narrowphase", "sleeping")


def snapshot(world, skip_joints=()) -> dict:
    """Everything needed to rebuild ``world`` through the public API (but the joints whose ids are
    in ``skip_joints``: the tools' own, such as the mouse drag's)."""
    bodies = world.bodies
    index = {b.id: i for i, b in enumerate(bodies)}
    return {
        "world": {f: getattr(world, f) for f in WORLD_FIELDS},
        "solver": world.solver,
        "settings": {name: world.settings_for(name).to_dict() for name in world.solvers},
        "bodies": [body_spec(b) for b in bodies],
        "springs": [{"a": index[sp.body_a.id], "b": None if sp.body_b is None else index[sp.body_b.id],
                     **{f: getattr(sp, f) for f in SPRING_FIELDS}} for sp in world.springs],
        "joints": [{"kind": j.kind, "a": index[j.body_a.id], "b": None if j.body_b is None else index[j.body_b.id],
                    "fields": joint_fields(j)} for j in world.joints if j.id not in skip_joints],
        # the bodies' own colours as loaded or saved (app data, app.body_colors), by place
        "colors": {index[i]: h for i, h in world.metadata.get("colors", {}).items() if i in index},
    }


def restore(snap: dict):
    w = physics.World(solver=snap["solver"])
    for f, v in snap["world"].items():
        setattr(w, f, v)
    for name, values in snap["settings"].items():
        try:
            w.settings_for(name).update(values)
        except (ValueError, KeyError, ImportError):
            pass
    bodies = [make_body(w, b) for b in snap["bodies"]]
    for s in snap["springs"]:
        w.add_spring(bodies[s["a"]], None if s["b"] is None else bodies[s["b"]],
                     **{f: s[f] for f in SPRING_FIELDS})
    for j in snap.get("joints", ()):
        make_joint(w, j["kind"], bodies[j["a"]], None if j["b"] is None else bodies[j["b"]], j["fields"])
    if snap.get("colors"):
        w.metadata["colors"] = {bodies[k].id: h for k, h in snap["colors"].items()}
    return w


class Document:
    def __init__(self, world, path: Path | None):
        self.world = world
        self.path = Path(path) if path else None
        self.history = History()
        self.refs = Refs()
        self.saved_state = 0        # history.state() when last saved or loaded (-1: never clean)
        self.clean_at = None        # history.version at which a timeline scrub undid every edit
        self.loaded = snapshot(world)

    @property
    def dirty(self) -> bool:
        if self.clean_at == self.history.version:
            return False
        return self.history.state() != self.saved_state

    def mark_saved(self, path: Path):
        """After a save (the editor's colours already in ``world.metadata``, as the file has them)."""
        self.path = Path(path)
        self.saved_state = self.history.state()
        self.loaded = snapshot(self.world)

    @property
    def title(self) -> str:
        name = self.path.name if self.path else "untitled"
        return name + (" *" if self.dirty else "")
