"""Scene files on disk and built-in worlds: where the shipped scenes live, loading with readable
errors, the demo world (no scene file) and the benchmark world (``--bodies N``)."""
from __future__ import annotations

import math
import sys
from pathlib import Path

import physics

ROOT = Path(__file__).resolve().parent.parent
SCENES_DIR = ROOT / "scenes"          # the shipped scenes: read-only to the sandbox
DEFAULT_SCENE = SCENES_DIR / "default.json"


def user_scenes_dir() -> Path:
    """The user's scene folder: ``scenes`` in platformdirs' user data dir (on Linux
    ``$XDG_DATA_HOME/stelkropp/scenes``, by default ``~/.local/share/stelkropp/scenes``)."""
    import platformdirs
    return Path(platformdirs.user_data_dir("stelkropp", appauthor=False)) / "scenes"


def is_shipped(path) -> bool:
    """Is ``path`` one of the scenes that ship with Stelkropp (under ``scenes/``)?"""
    try:
        p = Path(path).resolve()
        return SCENES_DIR.resolve() in p.parents
    except OSError:
        return False


def save_target(path) -> Path:
    """Where saving to ``path`` writes: a shipped scene goes to the user's scene folder under the
    same name (shipped scenes are never overwritten); any other path is itself."""
    path = Path(path)
    return user_scenes_dir() / path.name if is_shipped(path) else path


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


def scene_files(folder: Path | None = None) -> list[Path]:
    """The scene files in ``folder`` (default: the shipped scenes), sorted by name."""
    folder = SCENES_DIR if folder is None else Path(folder)
    if not folder.is_dir():
        return []
    return sorted(p for p in folder.glob("*.json") if not p.name.endswith(".schema.json"))


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




def initial_world(scene):
    """(world, path, load errors) to start with: ``scene``, else scenes/default.json, else the
    built-in demo world (with the reason the file did not load)."""
    if scene is not None:
        try:
            return load_world(scene), Path(scene), []
        except Exception as exc:  # noqa: BLE001
            errors = format_scene_error(exc)
            print(f"stelkropp: could not load {scene}:", *errors, sep="\n  ", file=sys.stderr)
            return demo_world(), None, errors
    if DEFAULT_SCENE.exists():
        try:
            return load_world(DEFAULT_SCENE), DEFAULT_SCENE, []
        except Exception as exc:  # noqa: BLE001
            return demo_world(), None, format_scene_error(exc)
    return demo_world(), None, []
