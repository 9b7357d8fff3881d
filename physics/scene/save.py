"""A World to scene data and scene files.

This module must not import ``physics.world`` (or anything that does):
``World.save_scene`` imports it, and the import graph stays acyclic.
"""
from __future__ import annotations

from .dump import to_dict
from .atomic import write_atomic
from .json_io import dumps


def scene_metadata(world) -> dict:
    """The name, description and camera a world was loaded with (``world.metadata``; edit it to
    change what is saved)."""
    return world.metadata


def scene_to_dict(world, meta: dict | None = None) -> dict:
    """Scene data for ``world`` (``meta``: name/description/camera, default ``world.metadata``)."""
    return to_dict(world, scene_metadata(world) if meta is None else meta)


def save_scene(world, path, name: str | None = None, description: str | None = None) -> None:
    """Write ``world`` as a scene file at ``path``, atomically (a crash never leaves half a file).

    ``name``/``description`` override the world's metadata in the file (not in the world).
    Raises OSError if the file cannot be written; the old file is then left as it was.
    """
    meta = dict(scene_metadata(world))
    if name is not None:
        meta["name"] = name
    if description is not None:
        meta["description"] = description
    write_atomic(path, dumps(scene_to_dict(world, meta)))
