"""A World to scene data and scene files.

This module must not import ``physics.world`` (or anything that does):
``World.save_scene`` imports it, and the import graph stays acyclic.
"""
from __future__ import annotations

from .. import metadata as meta_rules
from .atomic import scene_path, write_atomic
from .budget import work_problem
from .checks import Rejected, schema_problems, value_problems
from .dump import to_dict
from .json_io import dumps
from .problems import finish


def scene_metadata(world) -> dict:
    """The name, description and camera a world was loaded with (``world.metadata``; edit it to
    change what is saved)."""
    return world.metadata


def scene_to_dict(world, meta: dict | None = None) -> dict:
    """Scene data for ``world`` (``meta``: name/description/camera, default ``world.metadata``);
    ValueError naming a metadata field a file could not hold.  (The sandbox takes one per edit
    for undo, so the loader's checks run only when a file is written: ``save_scene``.)"""
    meta = scene_metadata(world) if meta is None else meta
    for key, value in meta.items():  # nested values may have been edited in place since they were set
        meta_rules.check(key, value)
    return to_dict(world, meta)


def _loadable(data) -> None:
    """ValueError listing what the loader would refuse in ``data`` (values and schema: what the
    world holds was checked when it was set, this is the net under it)."""
    too_much = work_problem(data)  # a world too big for any scene file is refused, not written
    problems, stop = ([too_much], True) if too_much else value_problems(data)
    if not stop:
        problems += schema_problems(data, Rejected(p for p, _ in problems))
    if problems:
        listed = "; ".join(f"{p}: {r}" for p, r in finish(problems)[:10])
        raise ValueError(f"the scene could not be loaded again, so it is not saved: {listed}")


def save_scene(world, path, name: str | None = None, description: str | None = None) -> None:
    """Write ``world`` as a scene file at ``path``, atomically (a crash never leaves half a file).

    ``name``/``description`` override the world's metadata in the file (not in the world).
    Raises OSError if the file cannot be written, ValueError naming the field if the scene could
    not be loaded again (a name with a lone surrogate); the old file is then left as it was.
    """
    target = scene_path(path)  # TypeError for what is no path, before any work
    meta = dict(scene_metadata(world))
    for key, value in (("name", name), ("description", description)):
        if value is not None:
            meta_rules.check(key, value, field="save_scene")
            meta[key] = value
    data = scene_to_dict(world, meta)
    _loadable(data)
    write_atomic(target, dumps(data))
