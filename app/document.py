"""The open scene: its world, file path, loaded snapshot (for reset), undo history, dirty flag."""
from __future__ import annotations

import math
from pathlib import Path

import physics

from .commands import BODY_FIELDS, SPRING_FIELDS, History, Refs

ROOT = Path(__file__).resolve().parent.parent
SCENES_DIR = ROOT / "scenes"
DEFAULT_SCENE = SCENES_DIR / "default.json"

WORLD_FIELDS = ("gravity", "dt", "integrator", "broadphase", "narrowphase", "sleeping")


def snapshot(world) -> dict:
    """Everything needed to rebuild ``world`` through the public API."""
    bodies = world.bodies
    index = {b.id: i for i, b in enumerate(bodies)}
    return {
        "world": {f: getattr(world, f) for f in WORLD_FIELDS},
        "solver": world.solver,
        "settings": {name: world.settings_for(name).to_dict() for name in world.solvers},
        "bodies": [{"shape": b.shape, **{f: getattr(b, f) for f in BODY_FIELDS}} for b in bodies],
        "springs": [{"a": index[sp.body_a.id], "b": None if sp.body_b is None else index[sp.body_b.id],
                     **{f: getattr(sp, f) for f in SPRING_FIELDS}} for sp in world.springs],
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
    bodies = [w.add_body(b["shape"], **{f: b[f] for f in BODY_FIELDS}) for b in snap["bodies"]]
    for s in snap["springs"]:
        w.add_spring(bodies[s["a"]], None if s["b"] is None else bodies[s["b"]],
                     **{f: s[f] for f in SPRING_FIELDS})
    return w


def demo_world():
    """A small built-in scene (used when no scene file is given and scenes/default.json is missing)."""
    w = physics.World()
    w.add_body(physics.Polygon.box(30, 1), kind="static", position=(0, -0.5), name="ground")
    w.add_body(physics.Polygon.box(1, 6), kind="static", position=(-14.5, 3))
    w.add_body(physics.Polygon.box(1, 6), kind="static", position=(14.5, 3))
    for row in range(8):
        for col in range(8 - row):
            w.add_body(physics.Polygon.box(1, 1), position=(-9 + col * 1.05 + row * 0.525, 0.5 + row * 1.0))
    for i in range(5):
        w.add_body(physics.Circle(0.45), position=(4 + i * 1.1, 6 + 0.3 * i))
    w.add_body(physics.Polygon.regular(6, 0.7), position=(7, 3))
    w.add_body(physics.Polygon.regular(3, 0.8), position=(9, 3))
    anchor = w.add_body(physics.Polygon.box(0.8, 0.8), position=(11, 7))
    w.add_spring(anchor, None, anchor_b=(11, 10), stiffness=120.0, damping=1.0, rest_length=2.0)
    return w


def bench_world(n: int):
    """``n`` dynamic boxes (and a few circles) raining into a container: the frame-time benchmark."""
    w = physics.World()
    width = max(20.0, math.sqrt(n) * 1.6)
    w.add_body(physics.Polygon.box(width + 2, 1), kind="static", position=(0, -0.5))
    w.add_body(physics.Polygon.box(1, width), kind="static", position=(-width / 2 - 0.5, width / 2))
    w.add_body(physics.Polygon.box(1, width), kind="static", position=(width / 2 + 0.5, width / 2))
    cols = int(width / 1.1)
    for i in range(n):
        r, c = divmod(i, cols)
        pos = (-width / 2 + 0.8 + c * 1.1 + 0.1 * (r % 2), 0.6 + r * 1.1)
        if i % 10 == 9:
            w.add_body(physics.Circle(0.45), position=pos)
        else:
            w.add_body(physics.Polygon.box(0.9, 0.9), position=pos)
    return w


def scene_files() -> list[Path]:
    if not SCENES_DIR.is_dir():
        return []
    return sorted(p for p in SCENES_DIR.glob("*.json") if not p.name.endswith(".schema.json"))


def format_scene_error(exc) -> list[str]:
    """A SceneError (or any load failure) as lines for the scene panel."""
    problems = getattr(exc, "problems", []) or []
    text = str(exc)
    lines = [text.splitlines()[0] if problems and text else text]
    for p in problems:
        if isinstance(p, (tuple, list)) and len(p) == 2:
            lines.append(f"{p[0]}: {p[1]}")
        else:
            lines.append(str(p))
    return lines


def load_world(path):
    """physics.load_scene(path), or a clear error; never returns a half-loaded world."""
    return physics.load_scene(str(path))


class Document:
    def __init__(self, world, path: Path | None):
        self.world = world
        self.path = Path(path) if path else None
        self.history = History()
        self.refs = Refs()
        self.saved_version = 0
        self.loaded = snapshot(world)

    @property
    def dirty(self) -> bool:
        return self.history.version != self.saved_version

    def mark_saved(self, path: Path):
        self.path = Path(path)
        self.saved_version = self.history.version
        self.loaded = snapshot(self.world)

    @property
    def title(self) -> str:
        name = self.path.name if self.path else "untitled"
        return name + (" *" if self.dirty else "")
