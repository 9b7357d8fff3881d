"""``--apply``: the chosen settings written into the scene file, everything else kept.

The file is read as data (not through a World, which would drop nothing but
would rewrite every body in canonical form), its ``world`` block gets the
choice's solver, settings, dt and integrator, the result is checked by building
it, and it is written atomically by the scene package's writer; a file that
fails any step is left exactly as it was.
"""
from __future__ import annotations

import os


def apply_choice(path, cand) -> dict:
    """Write ``cand`` into the scene file at ``path``; returns the new ``world`` block.

    SceneError if the file (or the result) is not a valid scene, OSError if it cannot be
    written; in both cases the file is unchanged."""
    from ..scene import read_scene, scene_from_dict
    from ..scene.atomic import write_atomic
    from ..scene.json_io import dumps
    from .search import world_fragment
    src = os.fspath(path)
    data = read_scene(src)
    scene_from_dict(data, source=src)  # refuse to edit a file that is already broken
    world = dict(data.get("world", {}))
    world.update(world_fragment(world, cand))
    data = {**data, "world": world} if "world" in data else _with_world(data, world)
    scene_from_dict(data, source=src)
    write_atomic(src, dumps(data))
    return world


def _with_world(data: dict, world: dict) -> dict:
    """``data`` with a ``world`` block placed after format/version/name/description."""
    out, placed = {}, False
    for k, v in data.items():
        if not placed and k not in ("format", "version", "name", "description"):
            out["world"] = world
            placed = True
        out[k] = v
    if not placed:
        out["world"] = world
    return out
