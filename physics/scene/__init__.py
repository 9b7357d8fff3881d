"""Scene files (JSON) to worlds and back.

    world = physics.load_scene("scenes/pyramid.json")     # SceneError lists every problem
    physics.save_scene(world, "out.json")                  # atomic: temp file + rename

``scene_from_dict`` / ``scene_to_dict`` do the same without files (the
sandbox uses them for undo snapshots and clipboard).  A world remembers the
name, description and camera of the scene it came from (``world.metadata``,
also ``scene_metadata(world)``), so saving keeps them.  The format is
documented in docs/scene-format.md.

One concept per module, imports running one way (this package imports the
world; the world imports only ``save``, lazily, for ``World.save_scene``):

    schema    the format as a JSON Schema, with every default and limit
    json_io   strict, bounded JSON parsing; canonical JSON text
    atomic    atomic file writes (temp file, fsync, rename; no temp file left behind)
    problems  JSON paths, value previews and one size-bounded SceneError
    checks    every problem in scene data as (JSON path, reason)
    load      scene data or files -> World
    dump      World -> scene data that reloads bit for bit
    save      scene data and files from a World (imports nothing that imports the world)
"""
from .load import load_scene, read_scene, scene_from_dict
from .save import save_scene, scene_metadata, scene_to_dict

__all__ = ["load_scene", "save_scene", "scene_from_dict", "scene_to_dict", "scene_metadata", "read_scene"]
