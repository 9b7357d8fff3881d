"""Scene files (JSON) to worlds and back.

    world = physics.load_scene("scenes/pyramid.json")     # SceneError lists every problem
    world.save_scene("out.json")                          # atomic: temp file + rename

``scene_from_dict`` / ``scene_to_dict`` do the same without files (the
sandbox uses them for undo snapshots and clipboard).  A world remembers the
name, description and camera of the scene it came from (``scene_metadata``),
so saving keeps them.  The format is documented in docs/scene-format.md;
the schema is physics/scene_schema.py.
"""
from __future__ import annotations

import os

from . import scene_schema as fmt
from .errors import SceneError
from .scene_checks import check
from . import scene_dump
from .scene_json import dumps, parse, read_text, write_atomic

__all__ = ["load_scene", "save_scene", "scene_from_dict", "scene_to_dict", "scene_metadata", "read_scene"]

def scene_metadata(world) -> dict:
    """The name, description and camera a world was loaded with (``world.metadata``; edit it to
    change what is saved)."""
    return world.metadata


def read_scene(path) -> dict:
    """Parse a scene file into plain data without checking it (SceneError for unreadable files)."""
    src = os.fspath(path)
    try:
        text = read_text(src, fmt.MAX_FILE_BYTES)
    except OSError as exc:
        raise _error(src, [("$", f"cannot read the file: {exc.strerror or exc}")]) from None
    except UnicodeDecodeError as exc:
        raise _error(src, [("$", f"not UTF-8 text ({exc.reason} at byte {exc.start})")]) from None
    except ValueError as exc:
        raise _error(src, [("$", str(exc))]) from None
    try:
        return parse(text)
    except ValueError as exc:  # JSONDecodeError, and ints too long to convert
        where = f"line {exc.lineno} column {exc.colno}: {exc.msg}" if hasattr(exc, "lineno") else str(exc)
        raise _error(src, [("$", f"not valid JSON ({where})")]) from None


def load_scene(path):
    """Load a scene file into a new World; raises SceneError listing every problem."""
    src = os.fspath(path)
    return scene_from_dict(read_scene(src), source=src)


def scene_from_dict(data, source: str = "<dict>"):
    """Build a World from scene data; raises SceneError (naming ``source``) listing every problem."""
    problems, shapes = check(data)
    if problems:
        raise _error(source, problems)
    return _build(data, shapes, source)


def scene_to_dict(world, meta: dict | None = None) -> dict:
    """Scene data for ``world`` (``meta``: name/description/camera, default the loaded ones)."""
    return scene_dump.to_dict(world, scene_metadata(world) if meta is None else meta)


def save_scene(world, path, name: str | None = None, description: str | None = None) -> None:
    """Write ``world`` as a scene file, atomically (a crash never leaves half a file)."""
    meta = dict(scene_metadata(world))
    if name is not None:
        meta["name"] = name
    if description is not None:
        meta["description"] = description
    data = scene_to_dict(world, meta)
    write_atomic(path, dumps(data))


def _error(source, problems) -> SceneError:
    n = len(problems)
    lines = [f"{source}: {n} problem{'s' if n != 1 else ''} in scene"]
    lines += [f"  {p}: {r}" for p, r in problems]
    return SceneError("\n".join(lines), problems=problems, path=source)


# -- building -----------------------------------------------------------------
def _build(data, shapes, source):
    from .world import World
    w = {**fmt.WORLD_DEFAULTS, **data.get("world", {})}
    try:
        world = World(gravity=w["gravity"], dt=w["dt"], solver=w["solver"], integrator=w["integrator"],
                      sleeping=w["sleeping"], broadphase=w["broadphase"], narrowphase=w["narrowphase"],
                      settings=w["settings"])
    except (ValueError, KeyError, ImportError) as exc:  # the checks should have caught it; say so anyway
        raise _error(source, [("world", str(exc))]) from None
    handles = {}
    for i, (b, shape) in enumerate(zip(data["bodies"], shapes)):
        handles[i] = _add_body(world, b, shape, f"bodies[{i}]", source)
    by_name = {b["name"]: handles[i] for i, b in enumerate(data["bodies"]) if "name" in b}
    for i, sp in enumerate(data.get("springs", [])):
        _add_spring(world, sp, by_name, f"springs[{i}]", source)
    scene_metadata(world).update({k: data[k] for k in ("name", "description", "camera") if k in data})
    return world


def _add_body(world, b, shape, path, source):
    kw = {**fmt.BODY_DEFAULTS, **{k: v for k, v in b.items() if k != "shape"}}
    try:
        return world.add_body(shape, **kw)
    except ValueError as exc:
        raise _error(source, [(path, str(exc))]) from None


def _add_spring(world, sp, by_name, path, source):
    kw = {**fmt.SPRING_DEFAULTS, **{k: v for k, v in sp.items() if k not in ("a", "b")}}
    b = None if sp["b"] is None else by_name[sp["b"]]
    try:
        return world.add_spring(by_name[sp["a"]], b, **kw)
    except ValueError as exc:
        raise _error(source, [(path, str(exc))]) from None
